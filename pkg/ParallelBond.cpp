#include "ParallelBond.hpp"
#include "ContactPieces.hpp"
#include "RangeChecks.hpp"
#include <core/Scene.hpp>

namespace yade {

YADE_PLUGIN((ParallelBondMat)(ParallelBondPhys)(Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys));
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
	// Called from outside the loop (utils.createInteraction, as installing joints does), the
	// dispatcher hands on the scene it last ran in: after O.load that one is gone.
	scene            = Omega::instance().getScene().get();
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
	if (geom) phys->normalBefore = geom->normal; // the frame turns from where the contact was made
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
	if (!joints) return false;
	interaction.phys = joints->jointPhys(interaction, *scene);
	return bool(interaction.phys);
}

} // namespace yade
