#include "DiscInteractionLoop.hpp"
#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

YADE_PLUGIN((DiscInteractionLoop));

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
	for (const auto& f : geomDispatcher->functors)
		if (dynamic_cast<Ig2_Sphere_Sphere_ScGeom*>(f.get())) discs = f;

	InteractionContainer& interactions = *scene->interactions;
	const long            size         = long(interactions.size());
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(guided) num_threads(ompThreads > 0 ? std::min(ompThreads, omp_get_max_threads()) : omp_get_max_threads())
#endif
	for (long i = 0; i < size; i++) {
		const shared_ptr<Interaction>& I  = interactions[i];
		const shared_ptr<Body>&        b1 = Body::byId(I->getId1(), scene);
		const shared_ptr<Body>&        b2 = Body::byId(I->getId2(), scene);
		if (!b1 || !b2) {
			scene->interactions->requestErase(I);
			continue;
		}
		// an interaction made explicitly (utils.createInteraction) has no law cached yet: dispatched once
		if (I->isReal() && discs && I->functorCache.geom == discs && I->functorCache.constLaw)
			updateDiscPair(*I, *b1, *b2);
		else if (!dispatched(I, b1, b2))
			continue;
		if (!I->functorCache.constLaw->go(I->geom, I->phys, I.get())) scene->interactions->requestErase(I);
	}
}

// Ig2_Sphere_Sphere_ScGeom::go for an existing, non-periodic contact, in the same order of
// operations (so that the results are the same to the last bit), without ScGeom::precompute's
// frame turn and shear increment: our laws form their own (toppling::FrameTurn).
void DiscInteractionLoop::updateDiscPair(Interaction& I, const Body& b1, const Body& b2) const
{
	auto&         geom = *static_cast<ScGeom*>(I.geom.get());
	const State & s1 = *b1.state, &s2 = *b2.state;
	const Real    r1 = static_cast<const Sphere*>(b1.shape.get())->radius, r2 = static_cast<const Sphere*>(b2.shape.get())->radius;
	Vector3r      normal = (s2.se3.position + Vector3r::Zero()) - s1.se3.position;
	const Real    norm   = normal.norm();
	normal /= norm;
	const Real penetrationDepth = r1 + r2 - norm;
	geom.contactPoint           = s1.se3.position + (r1 - 0.5 * penetrationDepth) * normal;
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
