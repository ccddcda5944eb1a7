#include "ParallelBond.hpp"
#include "ContactPieces.hpp"
#include "Validation.hpp"
#include <core/Omega.hpp>
#include <core/Scene.hpp>

namespace yade {

YADE_PLUGIN((ParallelBondMat)(ParallelBondPhys)(Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys)(Law2_ScGeom_ParallelBondPhys_ParallelBond));
CREATE_LOGGER(Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys);

using toppling::Range;

void ParallelBondMat::validate() const
{
	toppling::require("ParallelBondMat", "young", young, Range::positive());
	toppling::require("ParallelBondMat", "knKs", knKs, Range::positive());
	toppling::require("ParallelBondMat", "thickness", thickness, Range::positive());
	toppling::require("ParallelBondMat", "frictionAngle", frictionAngle, Range::angle());
	toppling::require("ParallelBondMat", "normalDamping", normalDamping, Range::dampingRatio());
	toppling::require("ParallelBondMat", "bondRadiusMultiplier", bondRadiusMultiplier, Range::positive());
	toppling::require("ParallelBondMat", "bondYoung", bondYoung, Range::nonNegative());
	toppling::require("ParallelBondMat", "bondKnKs", bondKnKs, Range::positive());
	toppling::require("ParallelBondMat", "bondTensileStrength", bondTensileStrength, Range::nonNegative());
	toppling::require("ParallelBondMat", "bondCohesion", bondCohesion, Range::nonNegative());
	toppling::require("ParallelBondMat", "bondFrictionAngle", bondFrictionAngle, Range::angle());
	toppling::require("ParallelBondMat", "bondNormalDamping", bondNormalDamping, Range::dampingRatio());
}

/********************** ParallelBondPhys **********************/

void ParallelBondPhys::installBond(Real overlap, const Vector3r& direction)
{
	if (!(direction.norm() > 0)) throw std::invalid_argument("ParallelBondPhys.installBond: direction must be a non-zero vector.");
	bondRefOverlap = overlap;
	bondDirection0 = direction.normalized();
	setBondState(intact);
}

// Any change of bond state starts the bond from zero force and updates the total stiffness.
void ParallelBondPhys::setBondState(int state)
{
	bondState       = state;
	bondNormalForce = 0;
	bondShearForce  = Vector3r::Zero();
	bondMoment      = 0;
	updateTotalStiffness();
}

void ParallelBondPhys::updateTotalStiffness()
{
	const bool b = isBonded();
	kn           = contactKn + (b ? bondKn * bondArea : 0);
	ks           = contactKs + (b ? bondKs * bondArea : 0);
	kr           = b ? bondKn * bondInertia : 0;
}

Real ParallelBondPhys::bondEnergy() const
{
	if (!isBonded()) return 0;
	return toppling::springEnergy(bondNormalForce, bondKn * bondArea) + toppling::springEnergy(bondShearForce.norm(), bondKs * bondArea)
	        + toppling::springEnergy(bondMoment, bondKn * bondInertia);
}

Real ParallelBondPhys::contactEnergy() const
{
	return toppling::springEnergy(contactNormalForce, contactKn) + toppling::springEnergy(contactShearForce.norm(), contactKs);
}

/********************** Ip2 **********************/

void Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys::go(
        const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& interaction)
{
	if (interaction->phys) return;
	const auto* mat1 = YADE_CAST<ParallelBondMat*>(m1.get());
	const auto* mat2 = YADE_CAST<ParallelBondMat*>(m2.get());
	try {
		mat1->validate();
		mat2->validate();
	} catch (const std::invalid_argument& e) { // inherited attributes (young, frictionAngle) set after construction
		// Throwing here would abort inside InteractionLoop's OpenMP loop: stop the run instead.
		LOG_ERROR(e.what() << " The run was stopped.");
		scene->stopAtIter = scene->iter + 1;
	}
	if (makeJoint(*interaction)) return;
	auto phys         = shared_ptr<ParallelBondPhys>(new ParallelBondPhys());
	interaction->phys = phys;

	const Real t = math::min(mat1->thickness, mat2->thickness);
	// Each disc is a spring 2 t Ec; the two act in series (PFC2D, Potyondy & Cundall 2004).
	phys->contactKn              = toppling::seriesStiffness(2 * mat1->thickness * mat1->young, 2 * mat2->thickness * mat2->young);
	phys->contactKs              = phys->contactKn / (0.5 * (mat1->knKs + mat2->knKs));
	phys->tangensOfFrictionAngle = math::tan(math::min(mat1->frictionAngle, mat2->frictionAngle));

	const Body& b1       = *Body::byId(interaction->getId1(), scene);
	const Body& b2       = *Body::byId(interaction->getId2(), scene);
	const Real  mEff     = toppling::effectiveMass(b1, b2);
	phys->contactDamping = toppling::dashpotCoefficient(math::max(mat1->normalDamping, mat2->normalDamping), mEff, phys->contactKn);

	// Bond properties are fixed now so that installing a bond later only needs the overlap.
	const auto* geom = dynamic_cast<const GenericSpheresContact*>(interaction->geom.get());
	const Real  r1 = geom ? geom->refR1 : 0, r2 = geom ? geom->refR2 : 0;
	const Real  rMin = (r1 > 0 && r2 > 0) ? math::min(r1, r2) : math::max(r1, r2);
	if (rMin > 0) {
		phys->bondRadius  = math::min(mat1->bondRadiusMultiplier, mat2->bondRadiusMultiplier) * rMin;
		phys->bondArea    = 2 * phys->bondRadius * t;
		phys->bondInertia = 2. / 3. * math::pow(phys->bondRadius, 3) * t;
		phys->bondKn      = math::min(mat1->bondYoung, mat2->bondYoung) / (r1 + r2);
		phys->bondKs      = phys->bondKn / (0.5 * (mat1->bondKnKs + mat2->bondKnKs));
		phys->bondDamping
		        = toppling::dashpotCoefficient(math::max(mat1->bondNormalDamping, mat2->bondNormalDamping), mEff, phys->bondKn * phys->bondArea);
	}
	phys->bondTensileStrength = math::min(mat1->bondTensileStrength, mat2->bondTensileStrength);
	phys->bondCohesion        = math::min(mat1->bondCohesion, mat2->bondCohesion);
	phys->bondTanFriction     = math::tan(math::min(mat1->bondFrictionAngle, mat2->bondFrictionAngle));
	phys->updateTotalStiffness();
}

bool Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys::makeJoint(Interaction& interaction) const
{
	const Body::id_t id1 = interaction.getId1(), id2 = interaction.getId2();
	if (!joints || !joints->straddles(id1, id2)) return false; // rock: skip the bond scan below
	const Body&    b1     = *Body::byId(id1, scene);
	const Body&    b2     = *Body::byId(id2, scene);
	const Vector3r branch = b2.state->pos - b1.state->pos;
	Real           turn   = 0; // discs without intact bonds: the joint as installed
	toppling::pairTurn(b1, b2, *scene, turn);
	const int set = joints->setFor(id1, id2, branch, turn, *scene);
	if (set < 0) return false;
	const auto* mat  = dynamic_cast<const SmoothJointMat*>(scene->materials[joints->jointMaterials[set]].get());
	const auto* geom = dynamic_cast<const ScGeom*>(interaction.geom.get());
	if (!mat || !geom) return false;
	interaction.phys = toppling::makeSmoothJoint(*mat, set, *geom, branch, turn);
	return true;
}

/********************** Law2 **********************/

bool Law2_ScGeom_ParallelBondPhys_ParallelBond::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	auto&      geom = *static_cast<ScGeom*>(ig.get());
	auto&      phys = *static_cast<ParallelBondPhys*>(ip.get());
	const Real un   = geom.penetrationDepth;
	if (!phys.isBonded() && un < 0) return false;

	const Body&     b1   = *Body::byId(I->getId1(), scene);
	const Body&     b2   = *Body::byId(I->getId2(), scene);
	const Vector3r& n    = geom.normal;
	const Vector3r  vRel = toppling::relativeVelocity(*b1.state, *b2.state, geom.contactPoint);
	if (!toppling::stepIsSmall(vRel, scene->dt, geom.refR1, geom.refR2)) {
		reportInstability(*I);
		return true;
	}
	// Shear increment from the contact point's relative velocity (PFC), not ScGeom's radius-based
	// one: the same lever arms as the torques applied below, so the law does no spurious work.
	const Vector3r du = toppling::tangential(vRel * scene->dt, n);

	// Contact: linear springs, no tension, Coulomb slider.
	if (un > 0) {
		geom.rotate(phys.contactShearForce);
		phys.contactNormalForce = phys.contactKn * un;
		phys.contactShearForce -= phys.contactKs * du;
		phys.isSlipping = toppling::coulombSlip(phys.contactShearForce, phys.contactNormalForce * phys.tangensOfFrictionAngle);
	} else {
		phys.contactNormalForce = 0;
		phys.contactShearForce  = Vector3r::Zero();
		phys.isSlipping         = false;
	}

	if (phys.isBonded()) {
		const Real spin = (b2.state->angVel.z() - b1.state->angVel.z()) * scene->dt;
		if (!updateBond(*I, geom, phys, du, spin) && un < 0) return false;
	}

	// Dashpots on the normal relative velocity (positive when separating).
	const Real c         = (un > 0 ? phys.contactDamping : 0) + (phys.isBonded() ? phys.bondDamping : 0);
	const Real dampingFn = c > 0 ? -c * vRel.dot(n) : 0;

	phys.normalForce = (phys.contactNormalForce + phys.bondNormalForce + dampingFn) * n;
	phys.shearForce  = phys.contactShearForce + phys.bondShearForce;
	applyForces(*I, b1.state->pos, b2.state->pos, geom.contactPoint, phys, phys.bondMoment);
	return true;
}

// Advances the bond by one step; false when it broke (the break is recorded).
bool Law2_ScGeom_ParallelBondPhys_ParallelBond::updateBond(const Interaction& I, ScGeom& geom, ParallelBondPhys& phys, const Vector3r& du, Real spin)
{
	const Real A = phys.bondArea, Ib = phys.bondInertia;
	geom.rotate(phys.bondShearForce);
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

	recordBreak(I, geom.contactPoint, mode, phys.bondEnergy());
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

namespace toppling {
	bool meanBondTurn(const Body& body, const Scene& scene, Real& turn)
	{
		Real sum   = 0;
		int  bonds = 0;
		for (const auto& idAndInteraction : body.intrs) {
			const Interaction& I = *idAndInteraction.second;
			// A class-index test, not a dynamic_cast: this runs for every bond of both discs of
			// every joint contact at every re-turn, where dynamic_cast took a third of the step.
			if (!I.phys || I.phys->getClassIndex() != ParallelBondPhys::getClassIndexStatic()) continue;
			const auto* bond = static_cast<const ParallelBondPhys*>(I.phys.get());
			if (!bond->isBonded()) continue;
			const Vector3r  d  = (*scene.bodies)[I.getId2()]->state->pos - (*scene.bodies)[I.getId1()]->state->pos;
			const Vector3r& d0 = bond->bondDirection0;
			sum += math::atan2(d0.x() * d.y() - d0.y() * d.x(), d0.dot(d));
			++bonds;
		}
		if (bonds < 2) return false;
		turn = sum / bonds;
		return true;
	}
} // namespace toppling

} // namespace yade
