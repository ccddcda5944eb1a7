// The joints of a scene: which disc pairs are joint contacts, of which set, and the rock's
// rotation that turns a joint's normal with the blocks on either side.
#pragma once

#include "SlopeGeometry.hpp"
#include <lib/base/AliasNamespaces.hpp>
#include <core/Body.hpp>
#include <core/IPhys.hpp>
#include <core/Interaction.hpp>
#include <algorithm>
#include <unordered_map>

namespace yade {

class Scene;
class SmoothJointMat;
class SmoothJointPhys;

// Which disc pairs are joint contacts, and with which joint set.
class JointSystem : public Serializable {
public:
	// A listed joint pair, or discs of two different blocks: the pair may get a smooth joint.
	bool straddles(Body::id_t id1, Body::id_t id2) const { return listedSet(id1, id2) >= 0 || differentBlocks(id1, id2); }
	// Joint set (index into jointMaterials) for a pair, or -1 for rock. `branch` is x2 - x1.
	int setFor(Body::id_t id1, Body::id_t id2, const Vector3r& branch, Real rockTurn, const Scene& scene) const;
	// The smooth joint of a new interaction between discs that straddle a joint, turned with the
	// rock around them; nullptr where the pair is rock. The one place that decides rock or joint.
	shared_ptr<IPhys>   jointPhys(const Interaction& interaction, const Scene& scene) const;
	void                addPair(Body::id_t id1, Body::id_t id2, int set);
	boost::python::list crossingPairs(const JointSetGeometry& set, const Vector2r& lo, const Vector2r& hi) const;
	boost::python::list addCrossingPairs(const JointSetGeometry& geometry, int set, const Vector2r& lo, const Vector2r& hi);
	void                assignBlocks(const boost::python::list& persistentSets);
	void                postLoad(JointSystem&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(JointSystem, Serializable,
		"The joints of a scene: pairs of discs that straddle a joint segment (found when joints are installed, "
		"``toppling.build.joints``), and the block of every disc. A pair listed here gets its set's smooth joint; a new "
		"contact between discs of two different blocks (blocks that slid or rotated into each other) gets the "
		"smooth joint of the set whose current normal is closest to the pair's centre line.",
		((vector<int>, jointMaterials, , , "Material id (in ``O.materials``) of the :yref:`SmoothJointMat` of each joint set."))
		((vector<int>, pairId1, , Attr::triggerPostLoad, "First disc of each joint pair."))
		((vector<int>, pairId2, , Attr::triggerPostLoad, "Second disc of each joint pair."))
		((vector<int>, pairSet, , Attr::triggerPostLoad, "Joint set of each joint pair."))
		((vector<int>, blockOfBody, , , "Block of each body (index = body id); -1 or missing: no block."))
		((bool, faceClosure, false, , "A joint contact made after the joints were installed starts with the closure of the two "
			"discs' faces (each disc's distance to the joint it faced at installation, ``faceDistance``) instead of stress-free. "
			"Where a sliding block's load sits on a few joint contacts, each new contact starting stress-free lets the block "
			"sink onto it, and a block that has turned presses its toe's face into the rock by its turn times its half-width, "
			"which such a contact does not resist. The closure is held within ``faceClosureLimit``."))
		((Real, faceClosureLimit, 0.2, Attr::triggerPostLoad, "Largest closure, either way, a new joint contact starts with (``faceClosure``), "
			"× the smaller radius of its discs (>= 0). A closure that large is interpenetration that stress-free contacts let "
			"happen, or faces that are not the planes in contact (e.g. at a block's corner): starting a soft joint contact "
			"at it releases its stored energy into the two discs at once."))
		((vector<int>, faceBody, , Attr::triggerPostLoad, "Disc of each recorded face distance."))
		((vector<int>, faceSide, , Attr::triggerPostLoad, "2 × joint set + 1 where the disc lies on the side its set's normal points to, + 0 on the other."))
		((vector<Real>, faceDistance, , Attr::triggerPostLoad, "Distance [m] from the disc's centre to the nearest joint it faces on that side, at installation (``addCrossingPairs``: "
			"discs within their radius plus twice the largest radius of a joint)."))
		,
		/*ctor*/,
		.def("addPair", &JointSystem::addPair, (boost::python::arg("id1"), boost::python::arg("id2"), boost::python::arg("set")),
			"Make the pair a joint contact of joint set ``set``.")
		.def("crossingPairs", &JointSystem::crossingPairs, (boost::python::arg("set"), boost::python::arg("lo"), boost::python::arg("hi")),
			"(id1, id2) of every real interaction between spheres whose centre-to-centre segment crosses a joint "
			"segment of the :yref:`JointSetGeometry` ``set`` (joints clipped to the box lo..hi).")
		.def("addCrossingPairs", &JointSystem::addCrossingPairs,
			(boost::python::arg("geometry"), boost::python::arg("set"), boost::python::arg("lo"), boost::python::arg("hi")),
			"Make every pair ``crossingPairs`` finds a joint contact of joint set ``set`` (whose material ``jointMaterials`` "
			"already lists) and record the distance of every disc near a joint of the set to the joint it faces "
			"(``faceDistance``); returns the pairs.")
		.def("assignBlocks", &JointSystem::assignBlocks, (boost::python::arg("persistentSets")),
			"Set ``blockOfBody`` for every sphere: discs in the same band of every given (fully persistent) set "
			"share a block.")
	);
	// clang-format on

private:
	// Pair key -> set. Kept up to date by addPair and postLoad, never built on demand: the Ip2
	// reads it from several threads at once.
	std::unordered_map<uint64_t, int> index;
	// (disc, side) -> position in faceDistance; kept as `index` is.
	std::unordered_map<uint64_t, size_t> faceIndex;
	void                                 rebuildIndex();
	void                                 rebuildFaceIndex();
	void                                 recordFace(Body::id_t id, int side, Real distance);
	void                                 recordFaces(const std::vector<toppling::geometry::Segment>& joints, int set, toppling::geometry::Vec2 normal);
	bool                                 faceOf(Body::id_t id, int side, Real& distance) const;
	void            closeFaces(SmoothJointPhys& phys, Body::id_t id1, Body::id_t id2, const SmoothJointMat& mat, const Vector3r& branch, Real rMin) const;
	int             listedSet(Body::id_t id1, Body::id_t id2) const;
	int             blockOf(Body::id_t id) const { return size_t(id) < blockOfBody.size() ? blockOfBody[id] : -1; }
	bool            differentBlocks(Body::id_t id1, Body::id_t id2) const { return blockOf(id1) >= 0 && blockOf(id2) >= 0 && blockOf(id1) != blockOf(id2); }
	static uint64_t faceKey(Body::id_t id, int side) { return (uint64_t(uint32_t(id)) << 32) | uint32_t(side); }
	static uint64_t key(Body::id_t a, Body::id_t b)
	{
		if (a > b) std::swap(a, b);
		return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
	}
};
REGISTER_SERIALIZABLE(JointSystem);

namespace toppling {
	// The rock's rotation at a disc [rad]: the mean turn of its intact bonds since they were
	// installed. Unlike the disc's own spin, this is defined by its neighbours, so a loose disc
	// spinning in a pore does not count. False with fewer than two intact bonds: a disc hanging
	// on one bond swings about its neighbour and would tilt its joint contacts.
	bool meanBondTurn(const Body& body, const Scene& scene, Real& turn);
	// The rock's rotation at a pair of discs [rad]: the mean of meanBondTurn of the two (or the one
	// that has intact bonds); false, turn untouched, when neither has.
	bool pairTurn(const Body& b1, const Body& b2, const Scene& scene, Real& turn);
	// v rotated by angle about z.
	Vector3r rotatedZ(const Vector3r& v, Real angle);
} // namespace toppling

} // namespace yade
