#include "DiscInteractionLoop.hpp"
#include "ParallelBondLaw.hpp"
#include "SmoothJoint.hpp"
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <core/TimeStepper.hpp>
#include <pkg/common/ForceResetter.hpp>
#include <pkg/common/InsertionSortCollider.hpp>
#include <pkg/common/PeriodicEngines.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/NewtonIntegrator.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <array>

namespace yade {

YADE_PLUGIN((DiscInteractionLoop));

namespace {
	// Our laws add to `sums` while it lives (also if the loop throws).
	struct SumsInUse {
		std::array<LawFunctor*, 2> laws;
		SumsInUse(std::array<LawFunctor*, 2> laws_, toppling::ForceSums* sums)
		        : laws(laws_)
		{
			set(sums);
		}
		~SumsInUse() { set(nullptr); }
		void set(toppling::ForceSums* sums) const
		{
			for (const auto& law : laws)
				if (law) static_cast<BreakingLaw*>(law)->sums = sums;
		}
	};

	template <class Law> shared_ptr<LawFunctor> lawOf(const LawDispatcher& dispatcher)
	{
		for (const auto& f : dispatcher.functors)
			if (dynamic_cast<Law*>(f.get())) return f;
		return nullptr;
	}
} // namespace

void DiscInteractionLoop::action()
{
	const bool removeUnseen = scene->interactions->iterColliderLastRun >= 0 && scene->interactions->iterColliderLastRun == scene->iter;
	if (scene->isPeriodic || !callbacks.empty() || loopOnSortedInteractions || removeUnseen) {
		flush();
		arraysCurrent = arraysThisStep = false;
		InteractionLoop::action();
		return;
	}
	lawDispatcher->scene  = scene;
	physDispatcher->scene = scene;
	geomDispatcher->scene = scene;
	geomDispatcher->updateScenePtr();
	physDispatcher->updateScenePtr();
	lawDispatcher->updateScenePtr();
	shared_ptr<IGeomFunctor> discs; // the pairs whose geometry is updated inline
	Real                     detection = 1;
	for (const auto& f : geomDispatcher->functors)
		if (const auto* ig2 = dynamic_cast<Ig2_Sphere_Sphere_ScGeom*>(f.get())) {
			discs     = f;
			detection = ig2->interactionDetectionFactor;
		}
	const shared_ptr<LawFunctor> bondLaw = lawOf<Law2_ScGeom_ParallelBondPhys_ParallelBond>(*lawDispatcher);
	const shared_ptr<LawFunctor> joints  = lawOf<Law2_ScGeom_SmoothJointPhys_SmoothJoint>(*lawDispatcher);
	auto* const                  law     = static_cast<Law2_ScGeom_ParallelBondPhys_ParallelBond*>(bondLaw.get());
	// The bonds in the array: within runSteps, unless their objects would have to be read back at once.
	const bool current = arraysCurrent && arraysValid();
	const bool arrays  = inRunSteps && bondLaw && discs && (current || readerBeforeNextLoop() != Reader::any);
	// the bodies' motion as DiscNewtonIntegrator left it, unless Python may have changed it since
	const bool moved = arrays && arraysCurrent && motionFresh;
	motionFresh      = false;
	arraysThisStep   = arrays;
	if (arrays && !current) build(discs.get(), bondLaw.get());
	if (!arrays) {
		flush();
		arraysCurrent = false;
	}
	if (!moved) gather();
#ifdef YADE_OPENMP
	const int threads = ompThreads > 0 ? std::min(ompThreads, omp_get_max_threads()) : omp_get_max_threads();
#else
	const int threads = 1;
#endif
	sums.reset(threads, motion.size());
	promoted.resize(threads);
	for (auto& list : promoted)
		list.clear(); // keeps its capacity: no allocation per step
	const SumsInUse inUse({ bondLaw.get(), joints.get() }, &sums);

	InteractionContainer& interactions = *scene->interactions;
	const long            size         = long(interactions.size());
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(guided) num_threads(threads)
#endif
	for (long i = 0; i < size; i++) {
		if (i + toppling::prefetchAhead < size) prefetch(i + toppling::prefetchAhead, arrays);
		if (arrays && slots[i].bond >= 0) {
			Slot&               slot = slots[i];
			toppling::DiscBond& bond = bonds[slot.bond];
			if (!law->interact(bond, slot.id1, slot.id2, motion[slot.id1], motion[slot.id2], radius[slot.id1], radius[slot.id2])) {
				scene->interactions->requestErase(bond.interaction);
				slot.bond = -1; // its physics is gone with it
			}
			continue;
		}
		const shared_ptr<Interaction>& I   = interactions[i];
		const Body::id_t               id1 = I->getId1(), id2 = I->getId2();
		const shared_ptr<Body>&        b1 = Body::byId(id1, scene);
		const shared_ptr<Body>&        b2 = Body::byId(id2, scene);
		if (!b1 || !b2) {
			scene->interactions->requestErase(I);
			continue;
		}
		const auto& cached = I->functorCache.constLaw;
		const bool  disc   = discs && I->functorCache.geom == discs;
		if (disc && !I->isReal() && apart(id1, id2, detection)) continue; // Ig2_Sphere_Sphere_ScGeom's first test
		// an interaction made explicitly (utils.createInteraction) has no law cached yet: dispatched once
		if (!(disc && I->isReal() && cached)) {
			if (dispatched(I, b1, b2) && !I->functorCache.constLaw->go(I->geom, I->phys, I.get())) scene->interactions->requestErase(I);
			else if (arrays && disc && I->isReal() && I->functorCache.constLaw == bondLaw)
#ifdef YADE_OPENMP
				promoted[omp_get_thread_num()].push_back(i);
#else
				promoted[0].push_back(i);
#endif
			continue;
		}
		auto& geom = *static_cast<ScGeom*>(I->geom.get());
		updateDiscPair(geom, id1, id2);
		bool keep;
		if (cached == bondLaw) keep = law->interact(*I, geom, *static_cast<ParallelBondPhys*>(I->phys.get()), motion[id1], motion[id2]);
		else if (cached == joints)
			keep = static_cast<Law2_ScGeom_SmoothJointPhys_SmoothJoint*>(joints.get())
			               ->interact(*I, geom, *static_cast<SmoothJointPhys*>(I->phys.get()), motion[id1], motion[id2]);
		else
			keep = cached->go(I->geom, I->phys, I.get());
		if (!keep) scene->interactions->requestErase(I);
	}
	sums.addTo(scene->forces);
	lastReader = Reader::any;
	if (!arrays) return;
	promote();
	unflushed  = true;
	lastReader = readerBeforeNextLoop(); // a law may have stopped the run in the loop
	if (lastReader != Reader::none) flush();
	if (lastReader == Reader::any) arraysCurrent = false; // what reads them may also change them
}

// Asks for what interaction i will read, a few interactions early: the bodies a pair joins lie
// anywhere in the per-body arrays, an interaction's objects anywhere in memory, and the step
// otherwise waits on each in turn.
void DiscInteractionLoop::prefetch(long i, bool arrays) const
{
	if (!arrays || slots[i].bond < 0) {
		__builtin_prefetch((*scene->interactions)[i].get());
		return;
	}
	const Slot& slot = slots[i];
	for (const Body::id_t id : { slot.id1, slot.id2 }) {
		const char* m = reinterpret_cast<const char*>(&motion[id]);
		__builtin_prefetch(m), __builtin_prefetch(m + sizeof(toppling::Kinematics) - 1);
		__builtin_prefetch(&radius[id]);
	}
	sums.prefetchPair(slot.id1, slot.id2);
}

// Runs `steps` steps in this thread; the disc path keeps the bonds in its array between them.
void DiscInteractionLoop::runSteps(long steps)
{
	if (steps < 0) throw std::invalid_argument("steps = " + std::to_string(steps) + ": give 0 or more");
	if (Omega::instance().isRunning()) throw std::runtime_error("runSteps: the scene is running (O.run); O.pause() it first.");
	Scene& sc = *Omega::instance().getScene();
	struct Running { // whatever ends the run, the objects get the bonds' state back
		DiscInteractionLoop& loop;
		explicit Running(DiscInteractionLoop& l)
		        : loop(l)
		{
			loop.inRunSteps = true;
		}
		~Running()
		{
			loop.inRunSteps = false;
			loop.flush();
			loop.settleOrientations();
			loop.arraysCurrent = loop.arraysThisStep = false;
		}
	} running(*this);
	sc.stopAtIter = sc.iter + steps;
	while (sc.iter < sc.stopAtIter) {
		sc.moveToNextTimeStep();
		if (PyErr_CheckSignals() == -1) boost::python::throw_error_already_set(); // Ctrl-C
	}
}

// Who may read (or change) the interactions' objects before this loop runs again: Python when
// control returns to it, a periodic engine when it is due, a time stepper at its update (reads
// only); an engine not known here may do anything at any step.
DiscInteractionLoop::Reader DiscInteractionLoop::readerBeforeNextLoop() const
{
	if (!inRunSteps || scene->subStepping || scene->iter + 1 >= scene->stopAtIter) return Reader::any;
	Reader reader = Reader::none;
	bool   after  = false; // the engines after this one run in this step, the others in the next
	for (const auto& e : scene->engines) {
		if (e.get() == this) {
			after = true;
			continue;
		}
		if (e->dead || dynamic_cast<const ForceResetter*>(e.get()) || dynamic_cast<const InsertionSortCollider*>(e.get())
		    || dynamic_cast<const NewtonIntegrator*>(e.get()))
			continue;
		if (auto* stepper = dynamic_cast<TimeStepper*>(e.get())) {
			// after this loop: its own test, which changes nothing (a GlobalStiffnessTimeStepper also
			// runs at the first step after a load); before the next loop: at every step, to be safe
			stepper->scene = scene;
			if (!after || stepper->isActivated()) reader = Reader::timeStepper;
			continue;
		}
		const auto* periodic = dynamic_cast<const PeriodicEngine*>(e.get());
		if (!periodic || due(*periodic)) return Reader::any;
	}
	return reader;
}

// Whether a periodic engine may run before this loop's next step (a wall-clock period a little
// early: it is read later than here); PeriodicEngine::isActivated's test, which cannot be called:
// it counts the runs.
bool DiscInteractionLoop::due(const PeriodicEngine& p) const
{
	const long next = scene->iter + 1;
	if (p.nDo >= 0 && p.nDone >= p.nDo) return false;
	if (p.firstIterRun > 0 && p.nDone == 0) return p.firstIterRun <= next;
	return (p.iterPeriod > 0 && next - p.iterLast >= p.iterPeriod) || (p.virtPeriod > 0 && scene->time + scene->dt - p.virtLast >= p.virtPeriod)
	        || (p.realPeriod > 0 && PeriodicEngine::getClock() + 0.1 - p.realLast >= p.realPeriod) || (p.nDone == 0 && p.initRun);
}

// How often the scene's InsertionSortCollider has run (-1: none): when it runs it inserts and
// erases interactions, and the container's order changes.
long DiscInteractionLoop::colliderActions() const
{
	for (const auto& e : scene->engines)
		if (const auto* collider = dynamic_cast<const InsertionSortCollider*>(e.get())) return collider->numAction;
	return -1;
}

bool DiscInteractionLoop::arraysValid() const
{
	return slots.size() == scene->interactions->size() && colliderActions() == colliderRuns && motion.size() == scene->bodies->size();
}

// One slot per interaction, in the container's order; a real disc pair under the parallel-bond
// law gets its entry in `bonds`, taken from its objects.
void DiscInteractionLoop::build(const IGeomFunctor* discs, const LawFunctor* bondLaw)
{
	flush(); // the objects are read below
	InteractionContainer& interactions = *scene->interactions;
	slots.resize(interactions.size());
	bonds.clear();
	for (size_t i = 0; i < interactions.size(); ++i) {
		Interaction& I = *interactions[i];
		slots[i]       = { -1, I.getId1(), I.getId2() };
		if (!I.isReal() || I.functorCache.geom.get() != discs || I.functorCache.constLaw.get() != bondLaw || !inPlane(I)) continue;
		slots[i].bond = int(bonds.size());
		bonds.emplace_back(I);
	}
	colliderRuns  = colliderActions();
	arraysCurrent = true;
	++builds;
	turn.resize(scene->bodies->size(), 0); // a pending turn is kept
	unflushed = false;
}

// The rock pairs that came into contact in this loop join the array (their objects are current).
void DiscInteractionLoop::promote()
{
	InteractionContainer& interactions = *scene->interactions;
	for (const auto& list : promoted)
		for (long i : list) {
			if (!inPlane(*interactions[i])) continue;
			slots[i].bond = int(bonds.size());
			bonds.emplace_back(*interactions[i]);
		}
}

// Whether both discs stay in one plane z = const. and turn about z only (as blockedDOFs "zXY", or
// a body not moved by forces and at rest out of the plane): the array's law works on x and y.
bool DiscInteractionLoop::inPlane(const Interaction& I) const
{
	const Body* b1 = Body::byId(I.getId1(), scene).get();
	const Body* b2 = Body::byId(I.getId2(), scene).get();
	if (!b1 || !b2 || b1->state->pos.z() != b2->state->pos.z()) return false;
	const unsigned outOfPlane = State::DOF_Z | State::DOF_RX | State::DOF_RY;
	for (const Body* b : { b1, b2 }) {
		const State& s = *b->state;
		if ((b->isDynamic() && (s.blockedDOFs & outOfPlane) != outOfPlane) || s.vel.z() != 0 || s.angVel.x() != 0 || s.angVel.y() != 0) return false;
	}
	return true;
}

// The discs' turns about z since their orientations were last written, into State.ori; the
// integrator defers them (a sine and a cosine per disc and step) while nothing reads them.
void DiscInteractionLoop::settleOrientations()
{
	if (!turnPending) return;
	for (const auto& b : *scene->bodies) {
		if (!b || turn[b->id] == 0) continue;
		State& s = *b->state;
		s.ori    = Quaternionr(AngleAxisr(turn[b->id], Vector3r::UnitZ())) * s.ori;
		s.ori.normalize();
		turn[b->id] = 0;
	}
	turnPending = false;
}

// The bonds' state and the geometry their law saw, back into their objects.
void DiscInteractionLoop::flush()
{
	if (!unflushed) return;
	for (const auto& slot : slots) {
		if (slot.bond < 0) continue;
		const toppling::DiscBond& bond = bonds[slot.bond];
		bond.store();
		updateDiscPair(static_cast<ScGeom&>(*bond.interaction->geom), slot.id1, slot.id2);
	}
	unflushed = false;
}

// Every body's motion and radius (0: not a sphere), in arrays by id: a pair then reads its two
// bodies from them, not from four scattered objects (Body, State, Shape each).
void DiscInteractionLoop::gather()
{
	auto& bodies = *scene->bodies;
	motion.resize(bodies.size());
	radius.assign(bodies.size(), 0);
	const int sphere = Sphere::getClassIndexStatic();
	for (const auto& b : bodies) {
		if (!b) continue;
		motion[b->id]      = toppling::Kinematics(*b->state);
		const Shape* shape = b->shape.get();
		if (shape && shape->getClassIndex() == sphere) radius[b->id] = static_cast<const Sphere*>(shape)->radius;
		else if (const auto* derived = dynamic_cast<const Sphere*>(shape))
			radius[b->id] = derived->radius;
	}
}

// Whether two spheres are too far apart for a contact (Ig2_Sphere_Sphere_ScGeom's test for a new one).
bool DiscInteractionLoop::apart(Body::id_t id1, Body::id_t id2, Real detection) const
{
	const Vector3r d = (motion[id2].pos + Vector3r::Zero()) - motion[id1].pos;
	return math::pow(detection * (radius[id1] + radius[id2]), 2) - d.squaredNorm() < 0;
}

// Ig2_Sphere_Sphere_ScGeom::go for an existing, non-periodic contact, in the same order of
// operations (so that the results are the same to the last bit), without ScGeom::precompute's
// frame turn and shear increment: our laws form their own (toppling::FrameTurn).
void DiscInteractionLoop::updateDiscPair(ScGeom& geom, Body::id_t id1, Body::id_t id2) const
{
	const Vector3r& pos1 = motion[id1].pos;
	const Real      r1 = radius[id1], r2 = radius[id2];
	Vector3r        normal = (motion[id2].pos + Vector3r::Zero()) - pos1;
	const Real      norm   = normal.norm();
	normal /= norm;
	const Real penetrationDepth = r1 + r2 - norm;
	geom.contactPoint           = pos1 + (r1 - 0.5 * penetrationDepth) * normal;
	geom.penetrationDepth       = penetrationDepth;
	geom.radius1                = r1;
	geom.radius2                = r2;
	geom.normal                 = normal;
}

// InteractionLoop's steps for one interaction (geometry, physics, the law's functor); false when
// it has no geometry, so no law to call.
bool DiscInteractionLoop::dispatched(const shared_ptr<Interaction>& I, const shared_ptr<Body>& b1_, const shared_ptr<Body>& b2_)
{
	if (b1_->isClump() || b2_->isClump() || !I->functorCache.geomExists || !b1_->shape || !b2_->shape) return false;
	bool swap = false;
	if (!I->functorCache.geom) {
		I->functorCache.geom = geomDispatcher->getFunctor2D(b1_->shape, b2_->shape, swap);
		if (!I->functorCache.geom) {
			I->functorCache.geomExists = false;
			return false;
		}
	}
	if (swap) I->swapOrder();
	const shared_ptr<Body>& b1      = swap ? b2_ : b1_;
	const shared_ptr<Body>& b2      = swap ? b1_ : b2_;
	const bool              wasReal = I->isReal();
	if (!I->functorCache.geom->go(b1->shape, b2->shape, *b1->state, *b2->state, Vector3r::Zero(), false, I)) {
		if (wasReal) scene->interactions->requestErase(I);
		return false;
	}
	if (!I->functorCache.phys) I->functorCache.phys = physDispatcher->getFunctor2D(b1->material, b2->material, swap);
	if (!I->functorCache.phys)
		throw std::runtime_error(
		        "Undefined or ambiguous IPhys dispatch for types " + b1->material->getClassName() + " and " + b2->material->getClassName() + ".");
	I->functorCache.phys->go(b1->material, b2->material, I);
	if (!wasReal) I->iterMadeReal = scene->iter;
	if (!I->functorCache.constLaw) I->functorCache.constLaw = lawDispatcher->getFunctor2D(I->geom, I->phys, swap);
	if (!I->functorCache.constLaw)
		throw std::runtime_error("No Law2 functor for geom " + I->geom->getClassName() + " and phys " + I->phys->getClassName() + ".");
	return true;
}

} // namespace yade
