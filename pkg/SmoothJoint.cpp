#include "SmoothJoint.hpp"
#include "ContactPieces.hpp"
#include "ParallelBond.hpp"
#include "Validation.hpp"
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>

namespace yade {

YADE_PLUGIN((SmoothJointMat)(JointSystem)(SmoothJointPhys)(Law2_ScGeom_SmoothJointPhys_SmoothJoint));

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

/********************** JointSystem **********************/

boost::python::list JointSystem::crossingPairs(const JointSetGeometry& set, const Vector2r& lo, const Vector2r& hi) const
{
	const std::vector<std::vector<::toppling::geometry::Segment>> joints { set.toGeometry().segments(toppling::box(lo, hi)) };
	const Scene&                                                  sc = *Omega::instance().getScene();
	boost::python::list                                           out;
	for (const auto& I : *sc.interactions) {
		if (!I->isReal()) continue;
		const Vector3r& p = (*sc.bodies)[I->getId1()]->state->pos;
		const Vector3r& q = (*sc.bodies)[I->getId2()]->state->pos;
		if (::toppling::geometry::crossedSet(joints, toppling::xy(p), toppling::xy(q)) >= 0)
			out.append(boost::python::make_tuple(I->getId1(), I->getId2()));
	}
	return out;
}

void JointSystem::assignBlocks(const boost::python::list& persistentSets)
{
	std::vector<::toppling::geometry::JointSet> sets;
	for (int i = 0; i < boost::python::len(persistentSets); ++i)
		sets.push_back(boost::python::extract<const JointSetGeometry&>(persistentSets[i])().toGeometry());
	::toppling::geometry::BlockIndex blocks(sets);
	const Scene&                     sc = *Omega::instance().getScene();
	blockOfBody.assign(sc.bodies->size(), -1);
	for (const auto& b : *sc.bodies)
		if (b && dynamic_cast<const Sphere*>(b->shape.get())) blockOfBody[b->id] = blocks.blockId(toppling::xy(b->state->pos));
}


void JointSystem::addPair(Body::id_t id1, Body::id_t id2, int set)
{
	pairId1.push_back(id1);
	pairId2.push_back(id2);
	pairSet.push_back(set);
	index[key(id1, id2)] = set;
}

void JointSystem::rebuildIndex()
{
	// The three lists may differ in length for a moment while Python assigns them one by one.
	index.clear();
	for (size_t i = 0; i < std::min({ pairId1.size(), pairId2.size(), pairSet.size() }); ++i)
		index[key(pairId1[i], pairId2[i])] = pairSet[i];
}

int JointSystem::listedSet(Body::id_t id1, Body::id_t id2) const
{
	const auto it = index.find(key(id1, id2));
	return it == index.end() ? -1 : it->second;
}

int JointSystem::setFor(Body::id_t id1, Body::id_t id2, const Vector3r& branch, Real rockTurn, const Scene& sc) const
{
	if (const int listed = listedSet(id1, id2); listed >= 0) return listed;
	if (!differentBlocks(id1, id2)) return -1;
	// Two blocks that were not in contact when the joints were installed: the set whose
	// (rotated) joint plane is most nearly perpendicular to the centre line.
	int  best          = -1;
	Real bestAlignment = -1;
	for (size_t s = 0; s < jointMaterials.size(); ++s) {
		const auto* mat = dynamic_cast<const SmoothJointMat*>(sc.materials[jointMaterials[s]].get());
		if (!mat) continue;
		const Real alignment = math::abs(toppling::rotatedZ(mat->normal, rockTurn).dot(branch.normalized()));
		if (alignment > bestAlignment) {
			bestAlignment = alignment;
			best          = int(s);
		}
	}
	return best;
}

/********************** geometry helpers **********************/

namespace toppling {
	bool pairTurn(const Body& b1, const Body& b2, const Scene& scene, Real& turn)
	{
		Real       a = 0, b = 0;
		const bool has1 = meanBondTurn(b1, scene, a), has2 = meanBondTurn(b2, scene, b);
		if (has1 && has2) turn = a + 0.5 * math::atan2(math::sin(b - a), math::cos(b - a)); // halfway along the shorter arc
		else if (has1 || has2)
			turn = has1 ? a : b;
		return has1 || has2;
	}

	Vector3r rotatedZ(const Vector3r& v, Real angle)
	{
		const Real c = math::cos(angle), s = math::sin(angle);
		return Vector3r(c * v.x() - s * v.y(), s * v.x() + c * v.y(), 0);
	}

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

Real SmoothJointPhys::elasticEnergy() const { return toppling::springEnergy(jointNormalForce, kn) + toppling::springEnergy(jointShearForce, ks); }

/********************** Law2 **********************/

void Law2_ScGeom_SmoothJointPhys_SmoothJoint::postLoad(Law2_ScGeom_SmoothJointPhys_SmoothJoint&)
{
	toppling::require("Law2_ScGeom_SmoothJointPhys_SmoothJoint", "turnInterval", turnInterval, toppling::Range::atLeastOne());
}

bool Law2_ScGeom_SmoothJointPhys_SmoothJoint::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	auto&       geom = *static_cast<ScGeom*>(ig.get());
	auto&       phys = *static_cast<SmoothJointPhys*>(ip.get());
	const Body& b1   = *Body::byId(I->getId1(), scene);
	const Body& b2   = *Body::byId(I->getId2(), scene);

	const Vector3r vRel = toppling::relativeVelocity(*b1.state, *b2.state, geom.contactPoint);
	if (!toppling::stepIsSmall(vRel, scene->dt, geom.refR1, geom.refR2)) {
		reportInstability(*I);
		return true;
	}
	if (!phys.isBonded() && geom.penetrationDepth < phys.releasePenetration) return false; // slid or opened apart
	Real turn = 0;
	if (scene->iter % turnInterval == 0 && toppling::pairTurn(b1, b2, *scene, turn)) phys.jointNormal = toppling::rotatedZ(phys.jointNormal0, turn);
	const Vector3r n  = phys.jointNormal;
	const Vector3r t  = Vector3r::UnitZ().cross(n);
	const Vector3r du = vRel * scene->dt;
	phys.overlap -= du.dot(n);

	const Real knA = phys.kn, ksA = phys.ks, A = phys.area;
	Real       fn = knA * phys.overlap;
	Real       fs = phys.jointShearForce - ksA * du.dot(t);
	if (phys.isBonded()) {
		int mode = 0;
		if (-fn / A >= phys.tensileStrength) mode = BreakingLaw::tension;
		else if (math::abs(fs) / A >= phys.cohesion + phys.tangensOfFrictionAngle * fn / A)
			mode = BreakingLaw::shear;
		if (mode) {
			phys.jointNormalForce = fn;
			phys.jointShearForce  = fs;
			recordBreak(*I, geom.contactPoint, mode, phys.elasticEnergy());
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
		const Real limit = phys.tangensOfFrictionAngle * fn;
		if (math::abs(fs) > limit) {
			const Real plasticSlip = (math::abs(fs) - limit) / ksA;
			phys.slip += plasticSlip;
			phys.overlap += plasticSlip * phys.tanDilation; // dilation against the confinement
			fn              = knA * phys.overlap;
			fs              = (fs < 0 ? -1 : 1) * phys.tangensOfFrictionAngle * fn;
			phys.isSlipping = true;
		}
	}
	phys.jointNormalForce = fn;
	phys.jointShearForce  = fs;
	phys.normalForce      = fn * n;
	phys.shearForce       = fs * t;
	applyForces(*I, b1.state->pos, b2.state->pos, geom.contactPoint, phys, 0);
	return true;
}

} // namespace yade
