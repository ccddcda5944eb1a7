// Joint sets of a 2D cross-section: parallel joints at a spacing, with optional rock bridges
// (persistence), or an explicit list of segments; and the block a point lies in.
// Pure C++17 (no YADE).
#pragma once

#include "Geometry2D.hpp"
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace yade {
namespace toppling {
	namespace geometry {

		constexpr double pi = 3.14159265358979323846;

		struct JointSet {
			Vec2                 origin;           // a point on one joint of the set [m]
			double               dipDeg       = 0; // joint line angle, counter-clockwise from +x [deg]
			double               spacing      = 0; // normal distance between joints [m] (0: only the joint through origin)
			double               jointLength  = std::numeric_limits<double>::infinity(); // length of each joint segment [m]
			double               bridgeLength = 0;                                       // intact rock between segments along a joint [m]
			double               phase        = 0; // where the first segment starts along the joint, from origin [m]
			std::vector<Segment> explicitSegments; // if not empty, these are the joints (spacing etc. unused)

			Vec2   direction() const { return { std::cos(dipDeg * pi / 180), std::sin(dipDeg * pi / 180) }; }
			Vec2   normal() const { return { -std::sin(dipDeg * pi / 180), std::cos(dipDeg * pi / 180) }; }
			double persistence() const { return std::isinf(jointLength) ? 1.0 : jointLength / (jointLength + bridgeLength); }

			// Throws std::invalid_argument naming the first attribute outside its range.
			void validate() const
			{
				if (!std::isfinite(origin.x) || !std::isfinite(origin.y)) fail("origin", origin.x, "a finite point");
				if (!(dipDeg >= -180 && dipDeg <= 180)) fail("dip", dipDeg, "in [-180, 180] deg");
				if (!explicitSegments.empty()) return;
				if (!(spacing >= 0 && std::isfinite(spacing))) fail("spacing", spacing, ">= 0 m (0: the one joint through origin)");
				if (!(jointLength > 0))
					fail("jointLength", jointLength, "> 0 m (the persistence jointLength/(jointLength+bridgeLength) is in (0, 1])");
				if (!(bridgeLength >= 0 && std::isfinite(bridgeLength)))
					fail("bridgeLength", bridgeLength, ">= 0 m (the persistence jointLength/(jointLength+bridgeLength) is in (0, 1])");
				if (!std::isfinite(phase)) fail("phase", phase, "finite");
			}

			// Index of the band between two joints that holds p (fully persistent sets).
			long band(Vec2 p) const
			{
				if (!explicitSegments.empty() || spacing == 0) return dot(p - origin, normal()) >= 0 ? 0 : -1;
				return long(std::floor(dot(p - origin, normal()) / spacing));
			}

			// The joint segments that cross the box (clipped to it).
			std::vector<Segment> segments(const Box& box) const
			{
				validate();
				if (!explicitSegments.empty()) return explicitSegments;
				const Vec2 n = normal(), d = direction();
				const Vec2 corners[4] = { box.min, { box.max.x, box.min.y }, box.max, { box.min.x, box.max.y } };
				double     sMin = std::numeric_limits<double>::infinity(), sMax = -sMin, tMin = sMin, tMax = -sMin;
				for (const Vec2& c : corners) {
					sMin = std::min(sMin, dot(c - origin, n));
					sMax = std::max(sMax, dot(c - origin, n));
					tMin = std::min(tMin, dot(c - origin, d));
					tMax = std::max(tMax, dot(c - origin, d));
				}
				std::vector<Segment> out;
				const long           first = spacing > 0 ? long(std::ceil(sMin / spacing)) : 0;
				const long           last  = spacing > 0 ? long(std::floor(sMax / spacing)) : 0;
				for (long k = first; k <= last; ++k) {
					const Vec2 foot = origin + (k * spacing) * n;
					for (auto [t0, t1] : pieces(tMin, tMax)) {
						Segment s { foot + t0 * d, foot + t1 * d };
						if (clip(s, box)) out.push_back(s);
					}
				}
				return out;
			}

		private:
			[[noreturn]] static void fail(const char* attribute, double value, const char* range)
			{
				std::ostringstream msg;
				msg << attribute << " = " << value << " is invalid: it must be " << range;
				throw std::invalid_argument(msg.str());
			}
			// Joint pieces along one line, as [t0, t1] intervals covering [tMin, tMax].
			std::vector<std::pair<double, double>> pieces(double tMin, double tMax) const
			{
				if (std::isinf(jointLength) || bridgeLength == 0) return { { tMin, tMax } };
				const double                           period = jointLength + bridgeLength;
				std::vector<std::pair<double, double>> out;
				for (double t = phase + std::floor((tMin - phase) / period) * period; t < tMax; t += period)
					out.push_back({ std::max(t, tMin), std::min(t + jointLength, tMax) });
				return out;
			}
			// Liang-Barsky clipping of s to the box; false when nothing is left.
			static bool clip(Segment& s, const Box& b)
			{
				const Vec2   d  = s.b - s.a;
				double       t0 = 0, t1 = 1;
				const double p[4] = { -d.x, d.x, -d.y, d.y };
				const double q[4] = { s.a.x - b.min.x, b.max.x - s.a.x, s.a.y - b.min.y, b.max.y - s.a.y };
				for (int i = 0; i < 4; ++i) {
					if (p[i] == 0) {
						if (q[i] < 0) return false;
						continue;
					}
					const double r = q[i] / p[i];
					if (p[i] < 0) t0 = std::max(t0, r);
					else
						t1 = std::min(t1, r);
				}
				if (t0 > t1) return false;
				const Vec2 a = s.a;
				s            = { a + t0 * d, a + t1 * d };
				return norm(s.b - s.a) > 0;
			}
		};

		// Blocks: regions between the joints of all sets. A block is named by its band index in
		// every fully persistent set; blockId numbers blocks in order of first query.
		class BlockIndex {
		public:
			explicit BlockIndex(std::vector<JointSet> sets)
			        : sets_(std::move(sets))
			{
			}
			int blockId(Vec2 p)
			{
				std::vector<long> key;
				for (const JointSet& s : sets_)
					if (s.explicitSegments.empty() && s.persistence() == 1) key.push_back(s.band(p));
				auto it = ids_.find(key);
				if (it != ids_.end()) return it->second;
				const int id = int(ids_.size());
				ids_.emplace(std::move(key), id);
				return id;
			}

		private:
			std::vector<JointSet>            sets_;
			std::map<std::vector<long>, int> ids_;
		};

		// The first of `joints` crossed by the segment p-q, or nullptr.
		inline const Segment* crossedSegment(const std::vector<Segment>& joints, Vec2 p, Vec2 q)
		{
			for (const Segment& j : joints)
				if (intersects({ p, q }, j)) return &j;
			return nullptr;
		}

		// How far p lies from the joints it faces: [s] the distance to the nearest of `joints` with p
		// on side s of it (1: the side the unit `normal` points to), infinity where none is within
		// `reach` of p. A joint faces p where p projects onto it.
		inline std::array<double, 2> facing(const std::vector<Segment>& joints, Vec2 p, Vec2 normal, double reach)
		{
			std::array<double, 2> nearest { std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity() };
			for (const Segment& j : joints) {
				const Vec2   along = j.b - j.a;
				const double t     = dot(p - j.a, along) / dot(along, along);
				const double d     = dot(p - j.a, normal);
				if (t < 0 || t > 1 || std::abs(d) > reach) continue;
				double& side = nearest[d > 0];
				side         = std::min(side, std::abs(d));
			}
			return nearest;
		}

	} // namespace geometry
} // namespace toppling
} // namespace yade
