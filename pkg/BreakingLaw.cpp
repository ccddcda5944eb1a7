#include "BreakingLaw.hpp"
#include "ContactPieces.hpp"
#include <core/Scene.hpp>

namespace yade {

YADE_PLUGIN((BreakingLaw));
CREATE_LOGGER(BreakingLaw);

void BreakingLaw::recordBreak(const Interaction& I, const Vector3r& where, const Vector3r& normal, Real size, int mode, Real energy)
{
#pragma omp critical(toppling_bond_breaks)
	{
		breakTime.push_back(scene->time);
		breakPosition.push_back(where);
		breakNormal.push_back(normal);
		breakSize.push_back(size);
		breakMode.push_back(mode);
		breakEnergy.push_back(energy);
		breakId1.push_back(I.getId1());
		breakId2.push_back(I.getId2());
	}
}

void BreakingLaw::applyForces(
        const Interaction& I, const Vector3r& pos1, const Vector3r& pos2, const Vector3r& contactPoint, const NormShearPhys& phys, Real couple)
{
	const Vector3r f = -phys.normalForce - phys.shearForce; // on body 1
	if (!f.allFinite() || !math::isfinite(couple)) {
		reportInstability(I);
		return;
	}
	if (sums) toppling::applyContact(*sums, I.getId1(), pos1, I.getId2(), pos2, contactPoint, f, Vector3r(0, 0, couple));
	else
		toppling::applyContact(scene->forces, I.getId1(), pos1, I.getId2(), pos2, contactPoint, f, Vector3r(0, 0, couple));
}

void BreakingLaw::reportInstability(const Interaction& I)
{
#pragma omp critical(toppling_instability)
	if (!unstable) {
		unstable          = true;
		scene->stopAtIter = scene->iter + 1;
		LOG_ERROR(
		        "Bodies " << I.getId1() << " and " << I.getId2()
		                  << " moved more than a tenth of a radius relative to each other in one step, "
		                     "or their force is not finite, at iteration "
		                  << scene->iter
		                  << ": the run is unstable and was stopped. Lower O.dt (or GlobalStiffnessTimeStepper's "
		                     "timestepSafetyCoefficient, <= 1); damping does not help: dashpots lower the stable step.");
	}
}

} // namespace yade
