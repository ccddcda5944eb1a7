// The interaction loop of a disc scene without YADE's generic machinery where it is not needed:
// every body's motion is gathered into arrays once per step; the geometry of a touching disc
// pair is updated inline from them (the same arithmetic as Ig2_Sphere_Sphere_ScGeom, without
// ScGeom's cached frame turn and shear increment, which our laws do not read) and its law is
// called directly on them. Everything else (new contacts,
// walls, boxes) goes through the dispatchers as in InteractionLoop, of which this is a drop-in
// subclass.
#pragma once

#include "ContactPieces.hpp"
#include <core/InteractionLoop.hpp>
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class DiscInteractionLoop : public InteractionLoop {
public:
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(DiscInteractionLoop, InteractionLoop,
		"An :yref:`InteractionLoop` for discs (spheres moving in the xy-plane): a touching pair of spheres has its "
		":yref:`ScGeom` updated inline and its law called without dispatch; results equal InteractionLoop's (one "
		"thread: bit for bit). Such pairs' :yref:`ScGeom.shearInc` is not updated (the parallel-bond and smooth-joint "
		"laws form their own shear increment and frame turn). Periodic scenes, callbacks and sorted loops run as in "
		"InteractionLoop. Constructed as InteractionLoop, from three lists of functors.",
		/*attrs*/,
		/*ctor*/,
		/*py*/
	);
	// clang-format on

private:
	std::vector<toppling::Kinematics> motion; // by body id, gathered at the start of each step
	std::vector<Real>                 radius; // by body id; 0: not a sphere
	toppling::ForceSums               sums;   // what the laws add during the loop
	void                              gather();
	bool                              dispatched(const shared_ptr<Interaction>& I, const shared_ptr<Body>& b1, const shared_ptr<Body>& b2);
	void                              updateDiscPair(ScGeom& geom, Body::id_t id1, Body::id_t id2) const;
	bool                              apart(Body::id_t id1, Body::id_t id2, Real detection) const;
};
REGISTER_SERIALIZABLE(DiscInteractionLoop);

} // namespace yade
