// The interaction loop of a disc scene without YADE's generic machinery where it is not needed:
// every body's motion is gathered into arrays once per step; the geometry of a touching disc
// pair is updated inline from them (the same arithmetic as Ig2_Sphere_Sphere_ScGeom, without
// ScGeom's cached frame turn and shear increment, which our laws do not read) and its law is
// called directly on them. Everything else (new contacts,
// walls, boxes) goes through the dispatchers as in InteractionLoop, of which this is a drop-in
// subclass.
//
// Within runSteps(), whose end is known, the parallel bonds' state is held in an array (one
// toppling::DiscBond per bonded or touching pair of discs in the xy-plane, in the interactions' order) rather than read from
// and written to every pair's scattered objects; the objects get it back (flush) wherever anything
// else may read them: at the end of runSteps (also when it ends by an exception), before an engine
// that reads interactions runs. After Python has had the scene the array is built again from the
// objects.
#pragma once

#include "BondArrays.hpp"
#include "ContactPieces.hpp"
#include <core/InteractionLoop.hpp>
#include <pkg/common/PeriodicEngines.hpp>
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class DiscInteractionLoop : public InteractionLoop {
public:
	void action() override;
	void runSteps(long steps);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(DiscInteractionLoop, InteractionLoop,
		"An :yref:`InteractionLoop` for discs (spheres moving in the xy-plane): a touching pair of spheres has its "
		":yref:`ScGeom` updated inline and its law called without dispatch; results equal InteractionLoop's (one "
		"thread: bit for bit). Such pairs' :yref:`ScGeom.shearInc` is not updated (the parallel-bond and smooth-joint "
		"laws form their own shear increment and frame turn). Periodic scenes, callbacks and sorted loops run as in "
		"InteractionLoop. Constructed as InteractionLoop, from three lists of functors.\n\n"
		"Within :yref:`runSteps<DiscInteractionLoop.runSteps>` the state of the parallel bonds between discs in the "
		"xy-plane is kept in an array (the law runs on its plane components, to the same results) and "
		"copied back to the interactions' physics and geometry at its end, before any other engine that reads "
		"interactions runs (a :yref:`PeriodicEngine` when it is due, a :yref:`TimeStepper` at its update); "
		"an engine this loop does not know of makes it use the objects at every step.",
		/*attrs*/,
		/*ctor*/,
		.def("runSteps", &DiscInteractionLoop::runSteps, (boost::python::arg("steps")),
			"Run ``steps`` time steps of the current scene in this thread (fewer if something sets "
			"``O.stopAtIter`` nearer, as a law does when the run goes unstable), the bonds in an array between "
			"them; Ctrl-C stops it between two steps.")
	);
	// clang-format on

private:
	friend class DiscNewtonIntegrator;
	enum class Reader { none, timeStepper, any }; // who may read the interactions before the next loop
	struct Slot {                                 // one per interaction, in the container's order
		int        bond;                      // index in `bonds`; -1: the interaction is handled through its objects
		Body::id_t id1, id2;
	};
	std::vector<toppling::Kinematics> motion; // by body id: gathered at the start of a step, or DiscNewtonIntegrator's
	std::vector<Real>                 radius; // by body id; 0: not a sphere
	toppling::ForceSums               sums;   // what the laws add during the loop
	std::vector<Slot>                 slots;
	std::vector<toppling::DiscBond>   bonds;
	std::vector<std::vector<long>>    promoted;                     // per thread: interactions that became bonds' this step
	bool                              arraysCurrent  = false;       // `slots` and `bonds` hold the scene's interactions
	bool                              unflushed      = false;       // `bonds` holds state the objects do not
	bool                              inRunSteps     = false;       // inside runSteps()
	bool                              arraysThisStep = false;       // this step's loop ran on the array
	bool                              motionFresh    = false;       // DiscNewtonIntegrator wrote `motion` after the last loop
	long                              builds         = 0;           // how often the array was built
	Reader                            lastReader     = Reader::any; // who may read the scene after this step's loop
	std::vector<Real>                 turn;                         // by body id: a disc's turn about z not yet in its State.ori
	bool                              turnPending  = false;
	long                              colliderRuns = -1; // the collider's numAction when `slots` were built
	void                              gather();
	void                              prefetch(long i, bool arrays) const;
	bool                              dispatched(const shared_ptr<Interaction>& I, const shared_ptr<Body>& b1, const shared_ptr<Body>& b2);
	void                              updateDiscPair(ScGeom& geom, Body::id_t id1, Body::id_t id2) const;
	bool                              apart(Body::id_t id1, Body::id_t id2, Real detection) const;
	Reader                            readerBeforeNextLoop() const;
	bool                              due(const PeriodicEngine& engine) const;
	long                              colliderActions() const;
	bool                              arraysValid() const;
	void                              build(const IGeomFunctor* discs, const LawFunctor* bondLaw);
	bool                              inPlane(const Interaction& I) const;
	void                              promote();
	void                              flush();
	void                              settleOrientations();
};
REGISTER_SERIALIZABLE(DiscInteractionLoop);

} // namespace yade
