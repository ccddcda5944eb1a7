#include "ParallelBondLaw.hpp"
#include "BondArrays.hpp"
#include "ContactPieces.hpp"
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <limits>

namespace yade {

YADE_PLUGIN((Law2_ScGeom_ParallelBondPhys_ParallelBond));

bool Law2_ScGeom_ParallelBondPhys_ParallelBond::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	const toppling::Kinematics k1(*Body::byId(I->getId1(), scene)->state), k2(*Body::byId(I->getId2(), scene)->state);
	return interact(*I, *static_cast<ScGeom*>(ig.get()), *static_cast<ParallelBondPhys*>(ip.get()), k1, k2);
}

bool Law2_ScGeom_ParallelBondPhys_ParallelBond::interact(
        const Interaction& I, ScGeom& geom, ParallelBondPhys& phys, const toppling::Kinematics& b1, const toppling::Kinematics& b2)
{
	return step(I, geom, phys, b1, b2);
}

bool Law2_ScGeom_ParallelBondPhys_ParallelBond::interact(
        const toppling::DiscContact& geom, toppling::BondEntry& bond, const toppling::Kinematics& b1, const toppling::Kinematics& b2)
{
	return step(*bond.interaction, geom, bond, b1, b2);
}

// One step of the law on a pair's geometry and physics: the physics object itself or its entry in
// the disc path's array of bonds (the same members, the same arithmetic).
template <class Geom, class Phys>
bool Law2_ScGeom_ParallelBondPhys_ParallelBond::step(
        const Interaction& I, const Geom& geom, Phys& phys, const toppling::Kinematics& b1, const toppling::Kinematics& b2)
{
	const Real un = geom.penetrationDepth;
	if (!phys.isBonded() && un < 0) return false;

	const Vector3r& n    = geom.normal;
	const Vector3r  vRel = toppling::relativeVelocity(b1, b2, geom.contactPoint);
	if (!toppling::stepIsSmall(vRel, scene->dt, geom.refR1, geom.refR2)) {
		reportInstability(I);
		return true;
	}
	// Shear increment from the contact point's relative velocity (PFC), not ScGeom's radius-based
	// one: the same lever arms as the torques applied below, so the law does no spurious work.
	const Vector3r du = toppling::tangential(vRel * scene->dt, n);
	// The frame turn from the normal this law saw last, not ScGeom's cache: the disc path
	// (DiscInteractionLoop) updates the geometry without it.
	const toppling::FrameTurn frame(phys.normalBefore, n, b1.angVel, b2.angVel, scene->dt);
	phys.normalBefore = n;

	// Contact: linear springs, no tension, Coulomb slider.
	if (un > 0) {
		frame.turn(phys.contactShearForce);
		phys.contactNormalForce = phys.contactKn * un;
		phys.contactShearForce -= phys.contactKs * du;
		phys.isSlipping = toppling::coulombSlip(phys.contactShearForce, phys.contactNormalForce * phys.tangensOfFrictionAngle);
	} else {
		phys.contactNormalForce = 0;
		phys.contactShearForce  = Vector3r::Zero();
		phys.isSlipping         = false;
	}

	if (phys.isBonded()) {
		const Real spin = (b2.angVel.z() - b1.angVel.z()) * scene->dt;
		if (!updateBond(I, geom, phys, frame, du, spin) && un < 0) return false;
	}

	// Dashpots on the normal relative velocity (positive when separating).
	const Real c         = (un > 0 ? phys.contactDamping : 0) + (phys.isBonded() ? phys.bondDamping : 0);
	const Real dampingFn = c > 0 ? -c * vRel.dot(n) : 0;

	phys.normalForce = (phys.contactNormalForce + phys.bondNormalForce + dampingFn) * n;
	phys.shearForce  = phys.contactShearForce + phys.bondShearForce;
	applyForces(I, b1.pos, b2.pos, geom.contactPoint, phys.normalForce, phys.shearForce, phys.bondMoment);
	return true;
}

// Advances the bond by one step; false when it broke (the break is recorded).
template <class Geom, class Phys>
bool Law2_ScGeom_ParallelBondPhys_ParallelBond::updateBond(
        const Interaction& I, const Geom& geom, Phys& phys, const toppling::FrameTurn& frame, const Vector3r& du, Real spin)
{
	const Real A = phys.bondArea, Ib = phys.bondInertia;
	frame.turn(phys.bondShearForce);
	phys.bondNormalForce = phys.bondKn * A * (geom.penetrationDepth - phys.bondRefOverlap);
	phys.bondShearForce -= phys.bondKs * A * du;
	phys.bondMoment -= phys.bondKn * Ib * spin;

	const Real sigma  = phys.bondNormalForce / A; // compression positive
	phys.bondSigmaMax = -sigma + math::abs(phys.bondMoment) * phys.bondRadius / Ib;
	phys.bondTauMax   = phys.bondShearForce.norm() / A;
	int mode          = ParallelBondPhys::intact;
	if (phys.bondSigmaMax >= phys.bondTensileStrength) mode = ParallelBondPhys::brokenTension;
	else if (phys.bondTauMax >= phys.bondCohesion + sigma * phys.bondTanFriction)
		mode = ParallelBondPhys::brokenShear;
	if (mode == ParallelBondPhys::intact) return true;

	recordBreak(I, geom.contactPoint, geom.normal, 2 * phys.bondRadius, mode, phys.bondEnergy());
	phys.setBondState(mode);
	return false;
}

Real Law2_ScGeom_ParallelBondPhys_ParallelBond::elasticEnergy() const
{
	Real energy = 0;
	for (const auto& I : *Omega::instance().getScene()->interactions) { // also before the first step
		if (!I->isReal()) continue;
		if (const auto* phys = dynamic_cast<const ParallelBondPhys*>(I->phys.get())) energy += phys->contactEnergy() + phys->bondEnergy();
	}
	return energy;
}

Real Law2_ScGeom_ParallelBondPhys_ParallelBond::criticalTimeStep() const
{
	const Scene&      sc = *Omega::instance().getScene();
	std::vector<Real> translational(sc.bodies->size(), 0), rotational(sc.bodies->size(), 0);
	for (const auto& I : *sc.interactions) {
		if (!I->isReal()) continue;
		// bonds and smooth joints alike (both are stress-free when installed)
		const auto* phys = dynamic_cast<const NormShearPhys*>(I->phys.get());
		const auto* geom = dynamic_cast<const GenericSpheresContact*>(I->geom.get());
		if (!phys || !geom) continue;
		const auto* bond = dynamic_cast<const ParallelBondPhys*>(phys);
		const Real  kr   = bond ? bond->kr : 0;
		const Real  k    = math::max(phys->kn, phys->ks);
		translational[I->getId1()] += k;
		translational[I->getId2()] += k;
		rotational[I->getId1()] += kr + phys->ks * math::pow(geom->refR1, 2);
		rotational[I->getId2()] += kr + phys->ks * math::pow(geom->refR2, 2);
	}
	Real dt2 = std::numeric_limits<Real>::infinity(); // squared
	for (const auto& b : *sc.bodies) {
		if (!b || !b->isDynamic()) continue;
		if (translational[b->id] > 0) dt2 = math::min(dt2, b->state->mass / translational[b->id]);
		if (rotational[b->id] > 0) dt2 = math::min(dt2, b->state->inertia.z() / rotational[b->id]);
	}
	return 1.41044 * math::sqrt(dt2); // sqrt(2), as GlobalStiffnessTimeStepper
}

int Law2_ScGeom_ParallelBondPhys_ParallelBond::countBonds(int state) const
{
	int count = 0;
	for (const auto& I : *Omega::instance().getScene()->interactions) {
		if (!I->isReal()) continue;
		if (const auto* phys = dynamic_cast<const ParallelBondPhys*>(I->phys.get())) count += (phys->bondState == state);
	}
	return count;
}

} // namespace yade
