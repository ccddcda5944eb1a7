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
bool Law2_ScGeom_ParallelBondPhys_ParallelBond::updateBond(
        const Interaction& I, const ScGeom& geom, ParallelBondPhys& phys, const toppling::FrameTurn& frame, const Vector3r& du, Real spin)
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

// interact() for two discs in the xy-plane, on their plane components: the same operations in
// the same order on every component that is not zero in the plane (the frame's twist, n.(w1+w2)
// n, is zero there), so the same results to the last bit. The geometry is formed here, as
// DiscInteractionLoop::updateDiscPair forms it.
bool Law2_ScGeom_ParallelBondPhys_ParallelBond::interact(
        toppling::DiscBond& b, Body::id_t id1, Body::id_t id2, const toppling::Kinematics& k1, const toppling::Kinematics& k2, Real r1, Real r2)
{
	const Real dx = (k2.pos.x() + Real(0)) - k1.pos.x(), dy = (k2.pos.y() + Real(0)) - k1.pos.y();
	const Real norm = math::sqrt(dx * dx + dy * dy);
	const Real nx = dx / norm, ny = dy / norm;
	const Real un = r1 + r2 - norm;
	if (!b.isBonded() && un < 0) return false;
	const Real cx = k1.pos.x() + (r1 - 0.5 * un) * nx, cy = k1.pos.y() + (r1 - 0.5 * un) * ny; // contact point
	const Real w1 = k1.angVel.z(), w2 = k2.angVel.z();
	const Real vx = (k2.vel.x() - w2 * (cy - k2.pos.y())) - (k1.vel.x() - w1 * (cy - k1.pos.y()));
	const Real vy = (k2.vel.y() + w2 * (cx - k2.pos.x())) - (k1.vel.y() + w1 * (cx - k1.pos.x()));
	const Real dt = scene->dt;
	{
		const Real r  = toppling::smallerRadius(b.refR1, b.refR2);
		const Real d2 = (vx * vx + vy * vy) * dt * dt;
		if (!(math::isfinite(d2) && (r <= 0 || d2 < 0.01 * r * r))) {
			reportInstability(*b.interaction);
			return true;
		}
	}
	const Real ux = vx * dt, uy = vy * dt, along = ux * nx + uy * ny;
	const Real dux = ux - along * nx, duy = uy - along * ny;
	const Real tilt = b.nx0 * ny - b.ny0 * nx; // the frame's turn about z since the last step
	b.nx0 = nx, b.ny0 = ny;
	const auto turn = [tilt](Real& sx, Real& sy) {
		const Real x = sx - sy * tilt;
		sy           = sy + sx * tilt;
		sx           = x;
	};

	if (un > 0) {
		turn(b.fcsx, b.fcsy);
		b.fcn = b.kn * un;
		b.fcsx -= b.ks * dux, b.fcsy -= b.ks * duy;
		const Real limit = b.fcn * b.tanPhi, fs = math::sqrt(b.fcsx * b.fcsx + b.fcsy * b.fcsy);
		b.slipping = !(fs <= limit); // as coulombSlip (a NaN force slips)
		if (b.slipping) {
			const Real scale = fs > 0 ? limit / fs : 0;
			b.fcsx *= scale, b.fcsy *= scale;
		}
	} else {
		b.fcn = b.fcsx = b.fcsy = 0;
		b.slipping              = false;
	}

	if (b.isBonded()) {
		turn(b.fbsx, b.fbsy);
		b.fbn = b.knA * (un - b.refOverlap);
		b.fbsx -= b.ksA * dux, b.fbsy -= b.ksA * duy;
		b.moment -= b.knI * ((w2 - w1) * dt);
		const Real sigma = b.fbn / b.area; // compression positive
		b.sigmaMax       = -sigma + math::abs(b.moment) * b.radius / b.inertia;
		b.tauMax         = math::sqrt(b.fbsx * b.fbsx + b.fbsy * b.fbsy) / b.area;
		int mode         = ParallelBondPhys::intact;
		if (b.sigmaMax >= b.tensileStrength) mode = ParallelBondPhys::brokenTension;
		else if (b.tauMax >= b.cohesion + sigma * b.tanPhiBond)
			mode = ParallelBondPhys::brokenShear;
		if (mode != ParallelBondPhys::intact) {
			b.store();
			recordBreak(*b.interaction, Vector3r(cx, cy, k1.pos.z()), Vector3r(nx, ny, 0), 2 * b.radius, mode, b.phys->bondEnergy());
			b.phys->setBondState(mode);
			b.state = mode;
			b.fbn = b.fbsx = b.fbsy = b.moment = 0;
			if (un < 0) return false;
		}
	}

	const Real c         = (un > 0 ? b.contactDamping : 0) + (b.isBonded() ? b.bondDamping : 0);
	const Real dampingFn = c > 0 ? -c * (vx * nx + vy * ny) : 0;
	const Real fn        = b.fcn + b.fbn + dampingFn;
	b.fnx = fn * nx, b.fny = fn * ny;
	b.fsx = b.fcsx + b.fbsx, b.fsy = b.fcsy + b.fbsy;
	const Real fx = -b.fnx - b.fsx, fy = -b.fny - b.fsy; // on body 1
	if (!(math::isfinite(fx) && math::isfinite(fy) && math::isfinite(b.moment))) {
		reportInstability(*b.interaction);
		return true;
	}
	const Real t1 = ((cx - k1.pos.x()) * fy - (cy - k1.pos.y()) * fx) - b.moment;
	const Real t2 = -((cx - k2.pos.x()) * fy - (cy - k2.pos.y()) * fx) + b.moment;
	sums->addPair(id1, id2, Vector3r(fx, fy, 0), Vector3r(0, 0, t1), Vector3r(0, 0, t2));
	return true;
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
