// Plane geometry for jointed slopes: points, segments, polygons with holes.
// Pure C++17 (no YADE), so it is unit-tested on its own with GoogleTest.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace yade {
namespace toppling {
	namespace geometry {

		struct Vec2 {
			double x = 0, y = 0;
		};
		inline Vec2   operator+(Vec2 a, Vec2 b) { return { a.x + b.x, a.y + b.y }; }
		inline Vec2   operator-(Vec2 a, Vec2 b) { return { a.x - b.x, a.y - b.y }; }
		inline Vec2   operator*(double s, Vec2 a) { return { s * a.x, s * a.y }; }
		inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
		inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
		inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }

		struct Segment {
			Vec2 a, b;
		};

		struct Box {
			Vec2 min { std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity() };
			Vec2 max { -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
			void extend(Vec2 p)
			{
				min = { std::min(min.x, p.x), std::min(min.y, p.y) };
				max = { std::max(max.x, p.x), std::max(max.y, p.y) };
			}
		};

		inline double distance(Vec2 p, const Segment& s)
		{
			const Vec2   d  = s.b - s.a;
			const double l2 = dot(d, d);
			const double t  = l2 > 0 ? std::clamp(dot(p - s.a, d) / l2, 0.0, 1.0) : 0.0;
			return norm(p - (s.a + t * d));
		}

		// Sign of the turn a->b->c: +1 left, -1 right, 0 collinear.
		inline int orientation(Vec2 a, Vec2 b, Vec2 c)
		{
			const double v = cross(b - a, c - a);
			return (v > 0) - (v < 0);
		}

		inline bool onSegment(Vec2 p, const Segment& s)
		{
			return std::min(s.a.x, s.b.x) <= p.x && p.x <= std::max(s.a.x, s.b.x) && std::min(s.a.y, s.b.y) <= p.y && p.y <= std::max(s.a.y, s.b.y);
		}

		// True when the closed segments share at least one point.
		inline bool intersects(const Segment& s, const Segment& t)
		{
			const int o1 = orientation(s.a, s.b, t.a), o2 = orientation(s.a, s.b, t.b);
			const int o3 = orientation(t.a, t.b, s.a), o4 = orientation(t.a, t.b, s.b);
			if (o1 != o2 && o3 != o4) return true;
			return (o1 == 0 && onSegment(t.a, s)) || (o2 == 0 && onSegment(t.b, s)) || (o3 == 0 && onSegment(s.a, t))
			        || (o4 == 0 && onSegment(s.b, t));
		}

		// A simple closed polygon (vertices in either order, last edge implied).
		class Polygon {
		public:
			explicit Polygon(std::vector<Vec2> vertices)
			        : v(std::move(vertices))
			{
				if (v.size() < 3) throw std::invalid_argument("polygon needs at least 3 vertices, got " + std::to_string(v.size()));
				for (size_t i = 0; i < v.size(); ++i) {
					if (!std::isfinite(v[i].x) || !std::isfinite(v[i].y))
						throw std::invalid_argument("vertex " + std::to_string(i) + " is not a finite point");
					if (norm(edge(i).b - edge(i).a) == 0)
						throw std::invalid_argument("polygon has a repeated vertex at index " + std::to_string(i));
				}
				if (const int i = firstSelfIntersection(); i >= 0)
					throw std::invalid_argument("polygon is self-intersecting: edge " + std::to_string(i) + " crosses a non-adjacent edge");
				if (!(area() > 0)) throw std::invalid_argument("polygon has no area: its vertices lie on one line");
			}
			size_t                   size() const { return v.size(); }
			const std::vector<Vec2>& vertices() const { return v; }
			Segment                  edge(size_t i) const { return { v[i], v[(i + 1) % v.size()] }; }

			double area() const
			{
				double a = 0;
				for (size_t i = 0; i < v.size(); ++i)
					a += cross(v[i], v[(i + 1) % v.size()]);
				return 0.5 * std::abs(a);
			}
			// Even-odd rule; points on the boundary count as inside.
			bool contains(Vec2 p) const
			{
				bool in = false;
				for (size_t i = 0; i < v.size(); ++i) {
					const Segment e = edge(i);
					if (distance(p, e) == 0) return true;
					if ((e.a.y > p.y) != (e.b.y > p.y) && p.x < e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y)) in = !in;
				}
				return in;
			}
			double distanceToBoundary(Vec2 p) const
			{
				double d = std::numeric_limits<double>::infinity();
				for (size_t i = 0; i < v.size(); ++i)
					d = std::min(d, distance(p, edge(i)));
				return d;
			}
			Box box() const
			{
				Box b;
				for (const Vec2& p : v)
					b.extend(p);
				return b;
			}

		private:
			std::vector<Vec2> v;
			int               firstSelfIntersection() const
			{
				const size_t n = v.size();
				for (size_t i = 0; i < n; ++i)
					for (size_t j = i + 1; j < n; ++j) {
						const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
						if (!adjacent && intersects(edge(i), edge(j))) return int(i);
					}
				return -1;
			}
		};

		// A polygon with holes; a point is inside when it is in the outer ring, outside every hole,
		// and at least `pad` away from all boundaries.
		class Region {
		public:
			explicit Region(Polygon outer, std::vector<Polygon> holes = {})
			        : outer_(std::move(outer))
			        , holes_(std::move(holes))
			{
				for (size_t k = 0; k < holes_.size(); ++k) {
					if (!inside(holes_[k], outer_))
						throw std::invalid_argument("hole " + std::to_string(k) + " is not inside the outer polygon: every hole must lie within it");
					for (size_t m = 0; m < k; ++m)
						if (!apart(holes_[k], holes_[m]))
							throw std::invalid_argument("hole " + std::to_string(k) + " overlaps hole " + std::to_string(m) + ": holes must be apart");
				}
			}
			bool contains(Vec2 p, double pad = 0) const
			{
				if (!outer_.contains(p) || (pad > 0 && outer_.distanceToBoundary(p) < pad)) return false;
				for (const Polygon& h : holes_)
					if (h.contains(p) || (pad > 0 && h.distanceToBoundary(p) < pad)) return false;
				return true;
			}
			double area() const
			{
				double a = outer_.area();
				for (const Polygon& h : holes_)
					a -= h.area();
				return a;
			}
			Box                         box() const { return outer_.box(); }
			const Polygon&              outer() const { return outer_; }
			const std::vector<Polygon>& holes() const { return holes_; }

		private:
			Polygon              outer_;
			std::vector<Polygon> holes_;

			static bool edgesCross(const Polygon& a, const Polygon& b)
			{
				for (size_t i = 0; i < a.size(); ++i)
					for (size_t j = 0; j < b.size(); ++j)
						if (intersects(a.edge(i), b.edge(j))) return true;
				return false;
			}
			// Strictly inside: no edges touch, and a vertex of the inner is in the outer.
			static bool inside(const Polygon& inner, const Polygon& outer) { return !edgesCross(inner, outer) && outer.contains(inner.vertices()[0]); }
			static bool apart(const Polygon& a, const Polygon& b)
			{
				return !edgesCross(a, b) && !a.contains(b.vertices()[0]) && !b.contains(a.vertices()[0]);
			}
		};

	} // namespace geometry
} // namespace toppling
} // namespace yade
