#include "SlopeGeometry.hpp"

namespace yade {

YADE_PLUGIN((PolygonRegion)(JointSetGeometry));

namespace toppling {
	toppling::geometry::Box box(const Vector2r& lo, const Vector2r& hi)
	{
		toppling::geometry::Box b;
		b.extend(xy(lo));
		b.extend(xy(hi));
		return b;
	}
} // namespace toppling

namespace {
	toppling::geometry::Polygon polygon(const vector<Vector2r>& vertices, const char* what)
	{
		std::vector<toppling::geometry::Vec2> v;
		for (const auto& p : vertices)
			v.push_back(toppling::xy(p));
		try {
			return toppling::geometry::Polygon(std::move(v));
		} catch (const std::invalid_argument& e) {
			throw std::invalid_argument(std::string("PolygonRegion.") + what + ": " + e.what());
		}
	}
} // namespace

/********************** PolygonRegion **********************/

toppling::geometry::Region PolygonRegion::toGeometry() const
{
	std::vector<toppling::geometry::Polygon> holes;
	size_t                                   start = 0;
	for (int n : holeSizes) {
		if (n < 0 || start + n > holeVertices.size())
			throw std::invalid_argument(
			        "PolygonRegion.holeSizes does not match holeVertices (" + std::to_string(holeVertices.size()) + " vertices).");
		holes.push_back(polygon(vector<Vector2r>(holeVertices.begin() + start, holeVertices.begin() + start + n), "holeVertices"));
		start += n;
	}
	try {
		return toppling::geometry::Region(polygon(vertices, "vertices"), std::move(holes));
	} catch (const std::invalid_argument& e) {
		if (std::string(e.what()).rfind("PolygonRegion.", 0) == 0) throw;
		throw std::invalid_argument(std::string("PolygonRegion.holeVertices: ") + e.what());
	}
}

boost::python::list PolygonRegion::containsMany(const boost::python::list& points, Real pad) const
{
	const auto          region = toGeometry();
	boost::python::list out;
	for (int i = 0; i < boost::python::len(points); ++i)
		out.append(region.contains(toppling::xy(Vector2r(boost::python::extract<Vector2r>(points[i]))), double(pad)));
	return out;
}

boost::python::tuple PolygonRegion::aabb() const
{
	const auto b = toGeometry().box();
	return boost::python::make_tuple(Vector2r(b.min.x, b.min.y), Vector2r(b.max.x, b.max.y));
}

/********************** JointSetGeometry **********************/

toppling::geometry::JointSet JointSetGeometry::toGeometry() const
{
	toppling::geometry::JointSet g;
	g.origin       = { double(origin.x()), double(origin.y()) };
	g.dipDeg       = double(dip);
	g.spacing      = double(spacing);
	g.jointLength  = double(jointLength);
	g.bridgeLength = double(bridgeLength);
	g.phase        = double(phase);
	if (segmentStarts.size() != segmentEnds.size())
		throw std::invalid_argument("JointSetGeometry: segmentStarts and segmentEnds must have the same length.");
	for (size_t i = 0; i < segmentStarts.size(); ++i)
		g.explicitSegments.push_back(
		        { { double(segmentStarts[i].x()), double(segmentStarts[i].y()) }, { double(segmentEnds[i].x()), double(segmentEnds[i].y()) } });
	try {
		g.validate();
	} catch (const std::invalid_argument& e) {
		throw std::invalid_argument(std::string("JointSetGeometry.") + e.what());
	}
	return g;
}

boost::python::list JointSetGeometry::segmentsPy(const Vector2r& lo, const Vector2r& hi) const
{
	boost::python::list out;
	for (const auto& s : toGeometry().segments(toppling::box(lo, hi)))
		out.append(boost::python::make_tuple(Vector2r(s.a.x, s.a.y), Vector2r(s.b.x, s.b.y)));
	return out;
}

} // namespace yade
