// What every toppling law shares: the record of broken bonds (cracks) and the stop on
// instability. The parallel-bond and the smooth-joint laws derive from it.
#pragma once

#include "ContactPieces.hpp"
#include <lib/base/AliasNamespaces.hpp>
#include <core/Dispatching.hpp>
#include <pkg/common/NormShearPhys.hpp>

namespace yade {

class BreakingLaw : public LawFunctor {
public:
	enum Mode { tension = 2, shear = 3 };
	// Records a break at `where`, across the unit `normal` (the bond's axis), of a bond `size` wide.
	void recordBreak(const Interaction& I, const Vector3r& where, const Vector3r& normal, Real size, int mode, Real energy);
	void reportInstability(const Interaction& I);
	// Applies the physics' force on body 2 (normalForce + shearForce, minus it on body 1) at the
	// contact point and a couple about z on body 2; a non-finite force stops the run instead.
	void
	applyForces(const Interaction& I, const Vector3r& pos1, const Vector3r& pos2, const Vector3r& contactPoint, const NormShearPhys& phys, Real couple);
	toppling::ForceSums* sums = nullptr; // set by DiscInteractionLoop during its loop: the forces go there, not to O.forces
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(BreakingLaw, LawFunctor,
		"Base of the toppling laws: keeps one record per broken bond (time, position, normal, size, mode, released "
		"energy, bodies) and stops the run when it goes unstable.",
		((vector<Real>, breakTime, , , "Simulated time of each bond break [s]."))
		((vector<Vector3r>, breakPosition, , , "Bond centre at each break [m]."))
		((vector<Vector3r>, breakNormal, , , "Unit normal of each broken bond (its axis, body 1 to body 2; a joint's normal) at the break [-]."))
		((vector<Real>, breakSize, , , "Width of each broken bond across its axis, the crack's length in the plane [m]."))
		((vector<int>, breakMode, , , "Mode of each break: 2 tension, 3 shear."))
		((vector<Real>, breakEnergy, , , "Elastic energy released by each break [J]."))
		((vector<int>, breakId1, , , "First body of each broken bond."))
		((vector<int>, breakId2, , , "Second body of each broken bond."))
		((bool, unstable, false, , "Set when a pair moved more than a tenth of its smaller radius relative to each "
			"other in one step (a time step far too large) or a force became non-finite; the run was then stopped "
			"(``O.stopAtIter``) with a message."))
	);
	// clang-format on
	DECLARE_LOGGER;
};
REGISTER_SERIALIZABLE(BreakingLaw);

} // namespace yade
