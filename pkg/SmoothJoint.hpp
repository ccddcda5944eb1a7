// Smooth-joint model for discs (Pierce 2007, Mas Ivars 2011; PFC2D form): the contact of two
// discs on opposite sides of a joint acts along the joint plane, not along their centre line,
// so blocks slide past each other without particle interlocking.
#pragma once

#include "BreakingLaw.hpp"
#include "ContactPieces.hpp"
#include <lib/base/AliasNamespaces.hpp>
#include <core/Material.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

// One joint set's mechanics and orientation; lives in O.materials, referenced by JointSystem.
class SmoothJointMat : public Material {
public:
	void validate() const;
	void postLoad(SmoothJointMat&) { validate(); }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR(SmoothJointMat, Material,
		"Mechanical parameters of one joint set (smooth joint, PFC2D form) and its orientation. Not assigned to "
		"bodies: :yref:`JointSystem` maps pairs of discs to it. Stiffnesses are per unit area (the thesis' "
		"N/m³); the joint area of a pair is $A=2\\bar\\lambda\\min(R_1,R_2)t$.",
		((Vector3r, normal, Vector3r(0, 1, 0), Attr::triggerPostLoad, "Unit normal of the joint plane (xy-plane vector) for discs that have not rotated; ``toppling.build.joints.install_joints`` sets it from the set's :yref:`JointSetGeometry.dip`."))
		((Real, normalStiffness, 1e9, Attr::triggerPostLoad, "Joint normal stiffness $k_n^j$ [N/m³] (> 0)."))
		((Real, shearStiffness, 1e9, Attr::triggerPostLoad, "Joint shear stiffness $k_s^j$ [N/m³] (> 0)."))
		((Real, frictionAngle, 0.5, Attr::triggerPostLoad, "Joint friction angle $\\phi_j$ [rad], in [0, π/2)."))
		((Real, dilationAngle, 0, Attr::triggerPostLoad, "Dilation angle $\\psi$ while slipping [rad], in [0, π/2)."))
		((Real, gap, 0, Attr::triggerPostLoad, "Joint aperture $g_j$ [m] (>= 0): normal closure, measured from the configuration when the joint "
			"contact was made, before the joint carries compression. 0: faces touching but stress-free."))
		((Real, radiusMultiplier, 1, Attr::triggerPostLoad, "$\\bar\\lambda$ of the joint area [-] (> 0)."))
		((Real, thickness, 1, Attr::triggerPostLoad, "Disc thickness $t$ [m] (> 0)."))
		((bool, bonded, false, , "Joint contacts start bonded (tensile strength and cohesion), then behave as unbonded once broken."))
		((Real, tensileStrength, 0, Attr::triggerPostLoad, "Bonded joint tensile strength [Pa] (>= 0)."))
		((Real, cohesion, 0, Attr::triggerPostLoad, "Bonded joint cohesion [Pa] (>= 0)."))
		,
		createIndex();
	);
	// clang-format on
	REGISTER_CLASS_INDEX(SmoothJointMat, Material);
};
REGISTER_SERIALIZABLE(SmoothJointMat);

class SmoothJointPhys : public FrictPhys {
public:
	bool isBonded() const { return bondState == 1; }
	// How a bonded joint holding normal force fn (compression positive) and shear force fs
	// breaks: BreakingLaw::tension at -fn/A >= tensileStrength, else BreakingLaw::shear at
	// |fs|/A >= cohesion + tan(phi) fn/A; 0 while it holds.
	int  failureMode(Real fn, Real fs) const;
	Real elasticEnergy() const;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(SmoothJointPhys, FrictPhys,
		"Physics of a smooth-joint contact. ``kn``/``ks`` hold $k^jA$ [N/m] (for the time step), "
		"``normalForce``/``shearForce`` the force on body 2 along the joint normal and plane.",
		((int, jointSet, -1, , "Joint set index (in :yref:`JointSystem.jointMaterials`)."))
		((Vector3r, jointNormal0, Vector3r(0, 1, 0), , "Joint normal for unrotated discs, pointing from body 1's side to body 2's [-]."))
		((Vector3r, jointNormal, Vector3r(0, 1, 0), , "Current joint normal: ``jointNormal0`` turned with the rock around the two discs."))
		((Real, area, 0, , "Joint area $A$ [m²]."))
		((Real, normalStiffness, 0, , "$k_n^j$ [N/m³]."))
		((Real, shearStiffness, 0, , "$k_s^j$ [N/m³]."))
		((Real, tanDilation, 0, , "$\\tan\\psi$ [-]."))
		((Real, overlap, 0, , "Normal closure along the joint normal [m]; starts at $-g_j$."))
		((Real, releasePenetration, 0, , "The unbonded contact ends once the discs' geometric penetration (``geom.penetrationDepth``) falls below this [m]: min(0, penetration when the joint contact was made) minus 5 % of the smaller radius."))
		((Real, jointNormalForce, 0, , "Normal force [N], compression positive."))
		((Real, jointShearForce, 0, , "Shear force along the joint tangent $\\hat z\\times\\hat n$ on body 2 [N]."))
		((Real, slip, 0, , "Accumulated plastic slip [m]."))
		((bool, isSlipping, false, , "Coulomb limit reached this step."))
		((int, bondState, 0, , "0 unbonded, 1 bonded, 2 broken in tension, 3 broken in shear."))
		((Real, tensileStrength, 0, , "Bonded tensile strength [Pa]."))
		((Real, cohesion, 0, , "Bonded cohesion [Pa]."))
		,
		createIndex();
		,
		.def("elasticEnergy", &SmoothJointPhys::elasticEnergy, "Elastic energy stored in the joint springs [J].")
	);
	// clang-format on
	REGISTER_CLASS_INDEX(SmoothJointPhys, FrictPhys);
};
REGISTER_SERIALIZABLE(SmoothJointPhys);

class Law2_ScGeom_SmoothJointPhys_SmoothJoint : public BreakingLaw {
public:
	bool go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I) override;
	// go() on the two bodies' kinematics, as given (DiscInteractionLoop gathers them).
	bool interact(const Interaction& I, const ScGeom& geom, SmoothJointPhys& phys, const toppling::Kinematics& b1, const toppling::Kinematics& b2);
	void postLoad(Law2_ScGeom_SmoothJointPhys_SmoothJoint&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Law2_ScGeom_SmoothJointPhys_SmoothJoint, BreakingLaw,
		"Smooth-joint law (Pierce 2007, Mas Ivars 2011; PFC2D). The relative displacement of the contact point is "
		"split along the joint normal $\\hat n$ and the joint plane: $\\Delta F_n = k_n^jA\\Delta u_n$, $\\Delta F_s=-k_s^jA\\Delta u_s$. "
		"Unbonded: no tension ($F_n=F_s=0$ while open), Coulomb slip $|F_s|\\le\\tan\\phi_j F_n$, and slipping by "
		"$\\Delta u_s^p$ closes the joint by $\\Delta u_s^p\\tan\\psi$ (dilation against the confinement). Bonded: "
		"breaks in tension at $-F_n/A\\ge\\sigma_t$, else in shear at $|F_s|/A\\ge c+\\tan\\phi_j F_n/A$ (recorded as a "
		"bond break) and goes on unbonded. No moment. An unbonded contact ends when its discs have moved apart (slid past each "
		"other or opened) further than they were when it was made; discs that come together later across the joint "
		"make a new, stress-free joint contact, so the load passes from pair to pair as a block slides. "
		"The normal turns with the rock on both sides: by the mean turn of the two discs' intact parallel bonds since "
		"they were installed (:yref:`ParallelBondPhys.bondDirection0`), not by the discs' own spin, which for a disc "
		"loose in a pore is meaningless; a disc counts only with at least two intact bonds, and the normal stays put "
		"while neither disc counts. The turn is updated every :yref:`turnInterval<Law2_ScGeom_SmoothJointPhys_SmoothJoint.turnInterval>` "
		"steps.",
		((int, turnInterval, 10, Attr::triggerPostLoad, "Steps between updates of the joint normal's turn (>= 1). The rock "
			"turns by its angular velocity times dt per step (1e-5 rad at 10 rad/s and dt = 1e-6 s), so a normal that "
			"lags by a few steps is exact far below the overlap's precision, while each update costs an atan2 per "
			"bond of both discs: updating every step took a quarter of the step of the tilting-table model."))
		,
		/*ctor*/,
		/*py*/
	);
	// clang-format on
	FUNCTOR2D(ScGeom, SmoothJointPhys);
};
REGISTER_SERIALIZABLE(Law2_ScGeom_SmoothJointPhys_SmoothJoint);

namespace toppling {
	// Smooth-joint physics for a pair of discs of radii r1, r2, with joint set `set` of material `mat`.
	shared_ptr<SmoothJointPhys> makeSmoothJoint(const SmoothJointMat& mat, int set, const ScGeom& geom, const Vector3r& branch, Real rockTurn);
} // namespace toppling

} // namespace yade
