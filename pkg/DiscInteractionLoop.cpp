#include "DiscInteractionLoop.hpp"
#include "ParallelBondLaw.hpp"
#include "SmoothJoint.hpp"
#include <array>
#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>

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
	const shared_ptr<LawFunctor> bonds = lawOf<Law2_ScGeom_ParallelBondPhys_ParallelBond>(*lawDispatcher);
	const shared_ptr<LawFunctor> joints = lawOf<Law2_ScGeom_SmoothJointPhys_SmoothJoint>(*lawDispatcher);
	gather();
#ifdef YADE_OPENMP
	sums.reset(ompThreads > 0 ? std::min(ompThreads, omp_get_max_threads()) : omp_get_max_threads(), motion.size());
#else
	sums.reset(1, motion.size());
#endif
	const SumsInUse inUse({ bonds.get(), joints.get() }, &sums);

	InteractionContainer& interactions = *scene->interactions;
	const long            size         = long(interactions.size());
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(guided) num_threads(ompThreads > 0 ? std::min(ompThreads, omp_get_max_threads()) : omp_get_max_threads())
#endif
	for (long i = 0; i < size; i++) {
		const shared_ptr<Interaction>& I  = interactions[i];
		const Body::id_t               id1 = I->getId1(), id2 = I->getId2();
		const shared_ptr<Body>&        b1 = Body::byId(id1, scene);
		const shared_ptr<Body>&        b2 = Body::byId(id2, scene);
		if (!b1 || !b2) {
			scene->interactions->requestErase(I);
			continue;
		}
		const auto& law  = I->functorCache.constLaw;
		const bool  disc = discs && I->functorCache.geom == discs;
		if (disc && !I->isReal() && apart(id1, id2, detection)) continue; // Ig2_Sphere_Sphere_ScGeom's first test
		// an interaction made explicitly (utils.createInteraction) has no law cached yet: dispatched once
		if (!(disc && I->isReal() && law)) {
			if (dispatched(I, b1, b2) && !I->functorCache.constLaw->go(I->geom, I->phys, I.get())) scene->interactions->requestErase(I);
			continue;
		}
		auto& geom = *static_cast<ScGeom*>(I->geom.get());
		updateDiscPair(geom, id1, id2);
		bool keep;
		if (law == bonds)
			keep = static_cast<Law2_ScGeom_ParallelBondPhys_ParallelBond*>(law.get())
			               ->interact(*I, geom, *static_cast<ParallelBondPhys*>(I->phys.get()), motion[id1], motion[id2]);
		else if (law == joints)
			keep = static_cast<Law2_ScGeom_SmoothJointPhys_SmoothJoint*>(law.get())
			               ->interact(*I, geom, *static_cast<SmoothJointPhys*>(I->phys.get()), motion[id1], motion[id2]);
		else
			keep = law->go(I->geom, I->phys, I.get());
		if (!keep) scene->interactions->requestErase(I);
	}
	sums.addTo(scene->forces);
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
		motion[b->id] = toppling::Kinematics(*b->state);
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
		throw std::runtime_error("Undefined or ambiguous IPhys dispatch for types " + b1->material->getClassName() + " and "
		                         + b2->material->getClassName() + ".");
	I->functorCache.phys->go(b1->material, b2->material, I);
	if (!wasReal) I->iterMadeReal = scene->iter;
	if (!I->functorCache.constLaw) I->functorCache.constLaw = lawDispatcher->getFunctor2D(I->geom, I->phys, swap);
	if (!I->functorCache.constLaw)
		throw std::runtime_error("No Law2 functor for geom " + I->geom->getClassName() + " and phys " + I->phys->getClassName() + ".");
	return true;
}

} // namespace yade
