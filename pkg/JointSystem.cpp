#include "JointSystem.hpp"
#include "ParallelBond.hpp"
#include "RangeChecks.hpp"
#include "SmoothJoint.hpp"
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>

namespace yade {

YADE_PLUGIN((JointSystem));

namespace {
	// The real interactions whose centre-to-centre segment crosses one of `joints`.
	std::vector<std::pair<Body::id_t, Body::id_t>> crossing(const std::vector<toppling::geometry::Segment>& joints)
	{
		const Scene&                                   sc = *Omega::instance().getScene();
		std::vector<std::pair<Body::id_t, Body::id_t>> found;
		for (const auto& I : *sc.interactions) {
			if (!I->isReal()) continue;
			const toppling::geometry::Vec2 p = toppling::xy((*sc.bodies)[I->getId1()]->state->pos);
			const toppling::geometry::Vec2 q = toppling::xy((*sc.bodies)[I->getId2()]->state->pos);
			if (toppling::geometry::crossedSegment(joints, p, q)) found.emplace_back(I->getId1(), I->getId2());
		}
		return found;
	}
} // namespace

boost::python::list JointSystem::crossingPairs(const JointSetGeometry& set, const Vector2r& lo, const Vector2r& hi) const
{
	boost::python::list out;
	for (const auto& [id1, id2] : crossing(set.toGeometry().segments(toppling::box(lo, hi))))
		out.append(boost::python::make_tuple(id1, id2));
	return out;
}

boost::python::list JointSystem::addCrossingPairs(const JointSetGeometry& geometry, int set, const Vector2r& lo, const Vector2r& hi)
{
	const Scene& sc = *Omega::instance().getScene();
	if (set < 0 || size_t(set) >= jointMaterials.size())
		throw std::invalid_argument(
		        "JointSystem.addCrossingPairs: set " + std::to_string(set) + " is not in jointMaterials (0 .. "
		        + std::to_string(int(jointMaterials.size()) - 1) + ")");
	const auto* mat = dynamic_cast<const SmoothJointMat*>(sc.materials.at(jointMaterials[set]).get());
	if (!mat) throw std::invalid_argument("JointSystem.addCrossingPairs: jointMaterials[" + std::to_string(set) + "] is not a SmoothJointMat");
	const std::vector<toppling::geometry::Segment> joints = geometry.toGeometry().segments(toppling::box(lo, hi));
	boost::python::list                            out;
	for (const auto& [id1, id2] : crossing(joints)) {
		addPair(id1, id2, set);
		out.append(boost::python::make_tuple(id1, id2));
	}
	recordFaces(joints, set, toppling::xy(mat->normal.normalized()));
	return out;
}

void JointSystem::recordFaces(const std::vector<toppling::geometry::Segment>& joints, int set, toppling::geometry::Vec2 normal)
{
	// Every disc that can touch one across the joint, not only the pairs across it now: a block
	// that slides brings its toe over rock that had none of it above.
	const Scene& sc   = *Omega::instance().getScene();
	Real         rMax = 0;
	for (const auto& b : *sc.bodies)
		if (const auto* s = b ? dynamic_cast<const Sphere*>(b->shape.get()) : nullptr) rMax = math::max(rMax, s->radius);
	for (const auto& b : *sc.bodies) {
		const auto* s = b ? dynamic_cast<const Sphere*>(b->shape.get()) : nullptr;
		if (!s) continue;
		const auto faces = toppling::geometry::facing(joints, toppling::xy(b->state->pos), normal, double(s->radius + 2 * rMax));
		for (int side = 0; side < 2; ++side)
			if (std::isfinite(faces[side])) recordFace(b->id, 2 * set + side, faces[side]);
	}
}

void JointSystem::assignBlocks(const boost::python::list& persistentSets)
{
	std::vector<toppling::geometry::JointSet> sets;
	for (int i = 0; i < boost::python::len(persistentSets); ++i)
		sets.push_back(boost::python::extract<const JointSetGeometry&>(persistentSets[i])().toGeometry());
	toppling::geometry::BlockIndex blocks(sets);
	const Scene&                   sc = *Omega::instance().getScene();
	blockOfBody.assign(sc.bodies->size(), -1);
	for (const auto& b : *sc.bodies)
		if (b && dynamic_cast<const Sphere*>(b->shape.get())) blockOfBody[b->id] = blocks.blockId(toppling::xy(b->state->pos));
}


void JointSystem::postLoad(JointSystem&)
{
	toppling::require("JointSystem", "faceClosureLimit", faceClosureLimit, toppling::Range::nonNegative());
	rebuildIndex();
	rebuildFaceIndex();
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

void JointSystem::recordFace(Body::id_t id, int side, Real distance)
{
	// A set installed again keeps each disc's nearer face.
	const auto it = faceIndex.find(faceKey(id, side));
	if (it != faceIndex.end()) {
		faceDistance[it->second] = math::min(faceDistance[it->second], distance);
		return;
	}
	faceIndex[faceKey(id, side)] = faceDistance.size();
	faceBody.push_back(id);
	faceSide.push_back(side);
	faceDistance.push_back(distance);
}

void JointSystem::rebuildFaceIndex()
{
	faceIndex.clear();
	for (size_t i = 0; i < std::min({ faceBody.size(), faceSide.size(), faceDistance.size() }); ++i)
		faceIndex[faceKey(faceBody[i], faceSide[i])] = i;
}

bool JointSystem::faceOf(Body::id_t id, int side, Real& distance) const
{
	const auto it = faceIndex.find(faceKey(id, side));
	if (it == faceIndex.end()) return false;
	distance = faceDistance[it->second];
	return true;
}

void JointSystem::closeFaces(SmoothJointPhys& phys, Body::id_t id1, Body::id_t id2, const SmoothJointMat& mat, const Vector3r& branch, Real rMin) const
{
	// phys.jointNormal points from disc 1 to disc 2: disc 2 lies on the side the set's normal points to when they agree.
	const int twoAhead = phys.jointNormal0.dot(mat.normal) > 0;
	Real      face1 = 0, face2 = 0;
	if (!faceOf(id1, 2 * phys.jointSet + 1 - twoAhead, face1) || !faceOf(id2, 2 * phys.jointSet + twoAhead, face2)) return;
	const Real closure = face1 + face2 - branch.dot(phys.jointNormal);
	const Real limit   = faceClosureLimit * rMin;
	phys.overlap       = math::max(-limit, math::min(limit, closure)) - mat.gap;
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

shared_ptr<IPhys> JointSystem::jointPhys(const Interaction& interaction, const Scene& sc) const
{
	const Body::id_t id1 = interaction.getId1(), id2 = interaction.getId2();
	if (!straddles(id1, id2)) return nullptr; // rock: skip the bond scan below
	const Body&    b1     = *(*sc.bodies)[id1];
	const Body&    b2     = *(*sc.bodies)[id2];
	const Vector3r branch = b2.state->pos - b1.state->pos;
	Real           turn   = 0; // discs without intact bonds: the joint as installed
	toppling::pairTurn(b1, b2, sc, turn);
	const int set = setFor(id1, id2, branch, turn, sc);
	if (set < 0) return nullptr;
	const auto* mat  = dynamic_cast<const SmoothJointMat*>(sc.materials[jointMaterials[set]].get());
	const auto* geom = dynamic_cast<const ScGeom*>(interaction.geom.get());
	if (!mat || !geom) return nullptr;
	auto phys = toppling::makeSmoothJoint(*mat, set, *geom, branch, turn);
	if (faceClosure) closeFaces(*phys, id1, id2, *mat, branch, toppling::smallerRadius(geom->refR1, geom->refR2));
	return phys;
}

/********************** the rock's rotation **********************/

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
} // namespace toppling

} // namespace yade
