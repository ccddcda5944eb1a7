// Slope geometry exposed to Python: a cross-section polygon with holes, and joint sets.
// Thin wrappers of the pure C++ in geometry/ (unit-tested on its own).
#pragma once

#include "geometry/JointSet.hpp"
#include <lib/base/AliasNamespaces.hpp>
#include <lib/serialization/Serializable.hpp>
#include <limits>

namespace yade {

namespace toppling {
	inline toppling::geometry::Vec2 xy(const Vector2r& p) { return { double(p.x()), double(p.y()) }; }
	inline toppling::geometry::Vec2 xy(const Vector3r& p) { return { double(p.x()), double(p.y()) }; }
	toppling::geometry::Box         box(const Vector2r& lo, const Vector2r& hi);
} // namespace toppling

// A cross-section: a simple polygon (possibly non-convex) minus holes.
class PolygonRegion : public Serializable {
public:
	toppling::geometry::Region toGeometry() const;
	bool                       contains(const Vector2r& p, Real pad) const { return toGeometry().contains(toppling::xy(p), double(pad)); }
	boost::python::list        containsMany(const boost::python::list& points, Real pad) const;
	Real                       area() const { return toGeometry().area(); }
	boost::python::tuple       aabb() const;
	void                       postLoad(PolygonRegion&)
	{
		if (!vertices.empty()) toGeometry(); // empty: not defined yet (default-constructed)
	}
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(PolygonRegion, Serializable,
		"A slope cross-section in the xy-plane: a simple polygon, possibly non-convex, minus holes. Bad input "
		"(fewer than 3 vertices, repeated vertices, self-intersection) raises ValueError. ``toppling.build.geometry`` "
		"wraps it as a YADE ``pack`` predicate.",
		((vector<Vector2r>, vertices, , Attr::triggerPostLoad, "Outer boundary [m], either orientation."))
		((vector<Vector2r>, holeVertices, , Attr::triggerPostLoad, "Vertices of all holes, one after another [m]."))
		((vector<int>, holeSizes, , Attr::triggerPostLoad, "Number of vertices of each hole."))
		,
		/*ctor*/,
		.def("contains", &PolygonRegion::contains, (boost::python::arg("p"), boost::python::arg("pad") = 0),
			"True when p is inside and at least ``pad`` from every boundary.")
		.def("containsMany", &PolygonRegion::containsMany, (boost::python::arg("points"), boost::python::arg("pad") = 0),
			"``contains`` for a list of points (one call, for speed).")
		.def("area", &PolygonRegion::area, "Area [m²].")
		.def("aabb", &PolygonRegion::aabb, "Bounding box (lo, hi) as two Vector2.")
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(PolygonRegion);

// Geometry of one joint set (exposed to Python): parallel joints at a spacing, with rock
// bridges, or explicit segments. Wraps toppling::geometry::JointSet.
class JointSetGeometry : public Serializable {
public:
	toppling::geometry::JointSet toGeometry() const;
	boost::python::list          segmentsPy(const Vector2r& lo, const Vector2r& hi) const;
	long                         band(const Vector2r& p) const { return toGeometry().band({ p.x(), p.y() }); }
	void                         postLoad(JointSetGeometry&) { toGeometry(); }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(JointSetGeometry, Serializable,
		"Where the joints of one set are, in the xy cross-section.",
		((Vector2r, origin, Vector2r::Zero(), Attr::triggerPostLoad, "A point on one joint of the set [m]."))
		((Real, dip, 0, Attr::triggerPostLoad, "Joint line angle, counter-clockwise from +x [deg] (a joint dipping 70° into a slope "
			"whose face looks towards +x: 180-70 = 110)."))
		((Real, spacing, 0, Attr::triggerPostLoad, "Normal distance between joints [m]; 0: only the joint through ``origin``."))
		((Real, jointLength, std::numeric_limits<Real>::infinity(), Attr::triggerPostLoad, "Length of each joint segment [m] (> 0)."))
		((Real, bridgeLength, 0, Attr::triggerPostLoad, "Rock bridge between joint segments [m] (>= 0); persistence = jointLength/(jointLength+bridgeLength)."))
		((Real, phase, 0, Attr::triggerPostLoad, "Where the first joint segment starts along the joint, from ``origin`` [m]."))
		((vector<Vector2r>, segmentStarts, , , "Explicit joints (merged joints, joints digitised from a photo): start points [m]."))
		((vector<Vector2r>, segmentEnds, , , "Explicit joints: end points [m]."))
		,
		/*ctor*/,
		.def("segments", &JointSetGeometry::segmentsPy, (boost::python::arg("lo"), boost::python::arg("hi")),
			"Joint segments within the box lo..hi, as a list of (start, end) Vector2 pairs.")
		.def("band", &JointSetGeometry::band, "Index of the band between two joints that holds a point (fully persistent sets).")
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(JointSetGeometry);

} // namespace yade
