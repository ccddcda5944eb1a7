#include "SmoothJoint.hpp"
#include "ContactPieces.hpp"
#include "JointSystem.hpp"
#include "RangeChecks.hpp"
#include <core/Omega.hpp>
#include <core/Scene.hpp>

namespace yade {

YADE_PLUGIN((SmoothJointMat)(SmoothJointPhys)(Law2_ScGeom_SmoothJointPhys_SmoothJoint));

using toppling::Range;

void SmoothJointMat::validate() const
{
	if (math::abs(normal.norm() - 1) > 1e-6 || normal.z() != 0) throw std::invalid_argument("SmoothJointMat.normal must be a unit vector in the xy-plane.");
	toppling::require("SmoothJointMat", "normalStiffness", normalStiffness, Range::positive());
	toppling::require("SmoothJointMat", "shearStiffness", shearStiffness, Range::positive());
	toppling::require("SmoothJointMat", "frictionAngle", frictionAngle, Range::angle());
	toppling::require("SmoothJointMat", "dilationAngle", dilationAngle, Range::angle());
	toppling::require("SmoothJointMat", "gap", gap, Range::nonNegative());
	toppling::require("SmoothJointMat", "radiusMultiplier", radiusMultiplier, Range::positive());
	toppling::require("SmoothJointMat", "thickness", thickness, Range::positive());
	toppling::require("SmoothJointMat", "tensileStrength", tensileStrength, Range::nonNegative());
	toppling::require("SmoothJointMat", "cohesion", cohesion, Range::nonNegative());
}

/********************** joint physics **********************/

namespace toppling {
	shared_ptr<SmoothJointPhys> makeSmoothJoint(const SmoothJointMat& mat, int set, const ScGeom& geom, const Vector3r& branch, Real rockTurn)
	{
		auto phys      = shared_ptr<SmoothJointPhys>(new SmoothJointPhys());
		phys->jointSet = set;
		// Orient the normal from body 1's side of the joint to body 2's.
		const Vector3r n             = rotatedZ(mat.normal, rockTurn);
		const Real     sign          = n.dot(branch) >= 0 ? 1 : -1;
		phys->jointNormal0           = sign * mat.normal;
		phys->jointNormal            = sign * n;
		const Real rMin              = smallerRadius(geom.refR1, geom.refR2);
		phys->area                   = 2 * mat.radiusMultiplier * rMin * mat.thickness;
		phys->normalStiffness        = mat.normalStiffness;
		phys->shearStiffness         = mat.shearStiffness;
		phys->kn                     = mat.normalStiffness * phys->area;
		phys->ks                     = mat.shearStiffness * phys->area;
		phys->tangensOfFrictionAngle = math::tan(mat.frictionAngle);
		phys->tanDilation            = math::tan(mat.dilationAngle);
		phys->overlap                = -mat.gap;
		// Slack of 5 % of the smaller radius: elastic shear and round-off must not end a loaded contact.
		phys->releasePenetration = math::min(Real(0), geom.penetrationDepth) - 0.05 * rMin;
		phys->bondState          = mat.bonded ? 1 : 0;
		phys->tensileStrength    = mat.tensileStrength;
		phys->cohesion           = mat.cohesion;
		return phys;
	}
} // namespace toppling

int SmoothJointPhys::failureMode(Real fn, Real fs) const
{
	const Real sigma = fn / area; // compression positive
	if (-sigma >= tensileStrength) return BreakingLaw::tension;
	if (math::abs(fs) / area >= cohesion + tangensOfFrictionAngle * sigma) return BreakingLaw::shear;
	return 0;
}

Real SmoothJointPhys::elasticEnergy() const { return toppling::springEnergy(jointNormalForce, kn) + toppling::springEnergy(jointShearForce, ks); }

/********************** Law2 **********************/

void Law2_ScGeom_SmoothJointPhys_SmoothJoint::postLoad(Law2_ScGeom_SmoothJointPhys_SmoothJoint&)
{
	toppling::require("Law2_ScGeom_SmoothJointPhys_SmoothJoint", "turnInterval", turnInterval, toppling::Range::atLeastOne());
}

bool Law2_ScGeom_SmoothJointPhys_SmoothJoint::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	const toppling::Kinematics k1(*Body::byId(I->getId1(), scene)->state), k2(*Body::byId(I->getId2(), scene)->state);
	return interact(*I, *static_cast<ScGeom*>(ig.get()), *static_cast<SmoothJointPhys*>(ip.get()), k1, k2);
}

bool Law2_ScGeom_SmoothJointPhys_SmoothJoint::interact(
        const Interaction& I, const ScGeom& geom, SmoothJointPhys& phys, const toppling::Kinematics& b1, const toppling::Kinematics& b2)
{
	const Vector3r vRel = toppling::relativeVelocity(b1, b2, geom.contactPoint);
	if (!toppling::stepIsSmall(vRel, scene->dt, geom.refR1, geom.refR2)) {
		reportInstability(I);
		return true;
	}
	if (!phys.isBonded() && geom.penetrationDepth < phys.releasePenetration) return false; // slid or opened apart
	Real turn = 0;
	if (scene->iter % turnInterval == 0 && toppling::pairTurn(*Body::byId(I.getId1(), scene), *Body::byId(I.getId2(), scene), *scene, turn))
		phys.jointNormal = toppling::rotatedZ(phys.jointNormal0, turn);
	const Vector3r n  = phys.jointNormal;
	const Vector3r t  = Vector3r::UnitZ().cross(n);
	const Vector3r du = vRel * scene->dt;
	phys.overlap -= du.dot(n);

	const Real knA = phys.kn, ksA = phys.ks;
	Real       fn = knA * phys.overlap;
	Real       fs = phys.jointShearForce - ksA * du.dot(t);
	if (phys.isBonded()) {
		if (const int mode = phys.failureMode(fn, fs)) {
			phys.jointNormalForce = fn;
			phys.jointShearForce  = fs;
			recordBreak(I, geom.contactPoint, n, 2 * toppling::smallerRadius(geom.refR1, geom.refR2), mode, phys.elasticEnergy());
			phys.bondState = mode;
		}
	}
	phys.isSlipping = false;
	if (!phys.isBonded()) {
		if (phys.overlap <= 0) { // open joint
			phys.jointNormalForce = phys.jointShearForce = 0;
			phys.normalForce = phys.shearForce = Vector3r::Zero();
			return true;
		}
		const Real plasticSlip = toppling::dilatantSlip(fn, fs, phys.overlap, knA, ksA, phys.tangensOfFrictionAngle, phys.tanDilation);
		phys.slip += plasticSlip;
		phys.isSlipping = plasticSlip > 0;
	}
	phys.jointNormalForce = fn;
	phys.jointShearForce  = fs;
	phys.normalForce      = fn * n;
	phys.shearForce       = fs * t;
	applyForces(I, b1.pos, b2.pos, geom.contactPoint, phys, 0);
	return true;
}

} // namespace yade
