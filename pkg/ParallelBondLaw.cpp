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
	applyForces(I, b1.pos, b2.pos, geom.contactPoint, phys, phys.bondMoment);
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

namespace {
	// (w z) x r, in the plane: the z and zero terms of the cross product in space left out.
	Vector2r spinCross(Real w, const Vector2r& r) { return Vector2r(-(w * r.y()), w * r.x()); }

	toppling::PlaneContact planeContact(const toppling::Kinematics& k1, const toppling::Kinematics& k2, Real r1, Real r2)
	{
		const Vector2r p1 = k1.pos.head<2>(), p2 = k2.pos.head<2>();
		Vector2r       n    = (p2 + Vector2r::Zero()) - p1;
		const Real     norm = n.norm();
		n /= norm;
		const Real     overlap = r1 + r2 - norm;
		const Vector2r point   = p1 + (r1 - 0.5 * overlap) * n;
		const Vector2r v       = (k2.vel.head<2>() + spinCross(k2.angVel.z(), point - p2)) - (k1.vel.head<2>() + spinCross(k1.angVel.z(), point - p1));
		return { n, point, v, overlap, k1.pos.z() };
	}

	// updateBond()'s forces, stresses and failure test on a bond of the disc path's array, its shear
	// force turned already: the mode it breaks in, or intact.
	int advanceBond(toppling::DiscBond& b, const toppling::PlaneContact& c, const Vector2r& du, Real spin)
	{
		b.fbn = b.knA * (c.overlap - b.refOverlap);
		b.fbs -= b.ksA * du;
		b.moment -= b.knI * spin;
		const Real sigma = b.fbn / b.area; // compression positive
		b.sigmaMax       = -sigma + math::abs(b.moment) * b.radius / b.inertia;
		b.tauMax         = b.fbs.norm() / b.area;
		if (b.sigmaMax >= b.tensileStrength) return ParallelBondPhys::brokenTension;
		if (b.tauMax >= b.cohesion + sigma * b.tanPhiBond) return ParallelBondPhys::brokenShear;
		return ParallelBondPhys::intact;
	}

	// toppling::FrameTurn in the plane: a shear force turned by the tilt nBefore x n about z.
	void turn(Vector2r& shear, Real tilt)
	{
		const Real x = shear.x() - shear.y() * tilt;
		shear.y()    = shear.y() + shear.x() * tilt;
		shear.x()    = x;
	}
} // namespace

// interact() for two discs in the xy-plane, on their plane components: the same operations in
// the same order on every component that is not zero in the plane (the frame's twist, n.(w1+w2)
// n, is zero there), so the same results to the last bit.
bool Law2_ScGeom_ParallelBondPhys_ParallelBond::interact(
        toppling::DiscBond& b, Body::id_t id1, Body::id_t id2, const toppling::Kinematics& k1, const toppling::Kinematics& k2, Real r1, Real r2)
{
	const toppling::PlaneContact c = planeContact(k1, k2, r1, r2);
	if (!b.isBonded() && c.overlap < 0) return false;
	const Real dt = scene->dt;
	if (!toppling::stepIsSmall(c.relativeVelocity, dt, b.refR1, b.refR2)) {
		reportInstability(*b.interaction);
		return true;
	}
	const Vector2r u    = c.relativeVelocity * dt;
	const Vector2r du   = u - u.dot(c.normal) * c.normal;
	const Real     tilt = b.normalBefore.x() * c.normal.y() - b.normalBefore.y() * c.normal.x();
	b.normalBefore      = c.normal;

	if (c.overlap > 0) {
		turn(b.fcs, tilt);
		b.fcn = b.kn * c.overlap;
		b.fcs -= b.ks * du;
		b.slipping = toppling::coulombSlip(b.fcs, b.fcn * b.tanPhi);
	} else {
		b.fcn = 0, b.fcs = Vector2r::Zero(), b.slipping = false;
	}
	if (b.isBonded()) {
		turn(b.fbs, tilt);
		const int mode = advanceBond(b, c, du, (k2.angVel.z() - k1.angVel.z()) * dt);
		if (mode != ParallelBondPhys::intact) {
			breakBond(b, c, mode);
			if (c.overlap < 0) return false;
		}
	}

	const Real c0        = (c.overlap > 0 ? b.contactDamping : 0) + (b.isBonded() ? b.bondDamping : 0);
	const Real dampingFn = c0 > 0 ? -c0 * c.relativeVelocity.dot(c.normal) : 0;
	b.normalForce        = (b.fcn + b.fbn + dampingFn) * c.normal;
	b.shearForce         = b.fcs + b.fbs;
	const Vector2r f     = -b.normalForce - b.shearForce; // on body 1
	if (!f.allFinite() || !math::isfinite(b.moment)) {
		reportInstability(*b.interaction);
		return true;
	}
	const Vector2r r1p = c.point - k1.pos.head<2>(), r2p = c.point - k2.pos.head<2>();
	const Real     t1 = (r1p.x() * f.y() - r1p.y() * f.x()) - b.moment;
	const Real     t2 = -(r2p.x() * f.y() - r2p.y() * f.x()) + b.moment;
	sums->addPair(id1, id2, Vector3r(f.x(), f.y(), 0), Vector3r(0, 0, t1), Vector3r(0, 0, t2));
	return true;
}

// A bond of the disc path's array broke: recorded, and its physics object told (the break's energy
// and the rock's rotation, toppling::meanBondTurn, read the object).
void Law2_ScGeom_ParallelBondPhys_ParallelBond::breakBond(toppling::DiscBond& b, const toppling::PlaneContact& c, int mode)
{
	b.store();
	recordBreak(*b.interaction, Vector3r(c.point.x(), c.point.y(), c.z), toppling::DiscBond::inSpace(c.normal), 2 * b.radius, mode, b.phys->bondEnergy());
	b.phys->setBondState(mode);
	b.state = mode, b.fbn = 0, b.fbs = Vector2r::Zero(), b.moment = 0;
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
