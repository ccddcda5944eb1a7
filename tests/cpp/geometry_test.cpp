// Plane geometry of jointed slopes, against hand-computed answers.
#include "geometry/JointSet.hpp"
#include <gtest/gtest.h>

using namespace yade::toppling::geometry;

namespace {
Polygon square(double size) { return Polygon({ { 0, 0 }, { size, 0 }, { size, size }, { 0, size } }); }
} // namespace

TEST(Polygon, AreaAndContainmentOfANonConvexL)
{
	const Polygon l({ { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } });
	EXPECT_DOUBLE_EQ(l.area(), 3.0);
	EXPECT_TRUE(l.contains({ 0.5, 1.5 }));
	EXPECT_TRUE(l.contains({ 1.5, 0.5 }));
	EXPECT_FALSE(l.contains({ 1.5, 1.5 })); // the notch
	EXPECT_TRUE(l.contains({ 2, 0.5 }));    // boundary counts as inside
	EXPECT_DOUBLE_EQ(l.distanceToBoundary({ 0.5, 0.25 }), 0.25);
}

TEST(Polygon, RejectsSelfIntersectionAndDegenerateInput)
{
	EXPECT_THROW(Polygon({ { 0, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } }), std::invalid_argument); // bow tie
	EXPECT_THROW(Polygon({ { 0, 0 }, { 1, 0 } }), std::invalid_argument);
	EXPECT_THROW(Polygon({ { 0, 0 }, { 1, 0 }, { 1, 0 }, { 0, 1 } }), std::invalid_argument);
	EXPECT_THROW(Polygon({ { 0, 0 }, { 1, 0 }, { 2, 0 } }), std::invalid_argument); // no area
	EXPECT_THROW(Polygon({ { 0, 0 }, { 1, 0 }, { 0, std::nan("") } }), std::invalid_argument);
}

TEST(Polygon, EitherOrientationIsTheSameRegion)
{
	const Polygon ccw({ { 0, 0 }, { 2, 0 }, { 2, 1 }, { 0, 1 } }), cw({ { 0, 1 }, { 2, 1 }, { 2, 0 }, { 0, 0 } });
	EXPECT_DOUBLE_EQ(cw.area(), ccw.area());
	for (Vec2 p : { Vec2 { 1, 0.5 }, Vec2 { 3, 0.5 }, Vec2 { 2, 1 } })
		EXPECT_EQ(cw.contains(p), ccw.contains(p));
}

TEST(Region, RejectsHolesOutsideTheOuterOrOverlapping)
{
	const Polygon hole({ { 4, 4 }, { 6, 4 }, { 6, 6 }, { 4, 6 } });
	EXPECT_THROW(Region(square(10), { Polygon({ { 11, 1 }, { 12, 1 }, { 12, 2 } }) }), std::invalid_argument); // outside
	EXPECT_THROW(Region(square(10), { Polygon({ { 9, 1 }, { 12, 1 }, { 12, 2 } }) }), std::invalid_argument);  // across
	EXPECT_THROW(Region(square(10), { hole, Polygon({ { 5, 5 }, { 7, 5 }, { 7, 7 } }) }), std::invalid_argument);
	EXPECT_THROW(Region(square(10), { hole, Polygon({ { 4.5, 4.5 }, { 5.5, 4.5 }, { 5, 5.5 } }) }), std::invalid_argument);
	EXPECT_NO_THROW(Region(square(10), { hole, Polygon({ { 1, 1 }, { 2, 1 }, { 2, 2 } }) }));
}

TEST(Region, HolesAndPadding)
{
	const Region r(square(10), { Polygon({ { 4, 4 }, { 6, 4 }, { 6, 6 }, { 4, 6 } }) });
	EXPECT_DOUBLE_EQ(r.area(), 96.0);
	EXPECT_TRUE(r.contains({ 2, 2 }));
	EXPECT_FALSE(r.contains({ 5, 5 }));
	EXPECT_FALSE(r.contains({ 3.5, 5 }, 1.0)); // 0.5 from the hole
	EXPECT_TRUE(r.contains({ 3.5, 5 }, 0.4));
	EXPECT_FALSE(r.contains({ 0.2, 5 }, 0.5));
}

TEST(Segments, IntersectionIncludingTouchingAndCollinear)
{
	EXPECT_TRUE(intersects({ { 0, 0 }, { 2, 2 } }, { { 0, 2 }, { 2, 0 } }));
	EXPECT_TRUE(intersects({ { 0, 0 }, { 1, 0 } }, { { 1, 0 }, { 1, 1 } }));
	EXPECT_TRUE(intersects({ { 0, 0 }, { 2, 0 } }, { { 1, 0 }, { 3, 0 } }));
	EXPECT_FALSE(intersects({ { 0, 0 }, { 1, 0 } }, { { 2, 0 }, { 3, 0 } }));
	EXPECT_FALSE(intersects({ { 0, 0 }, { 1, 1 } }, { { 0, 1 }, { 0.4, 0.6 + 1e-9 } }));
	EXPECT_DOUBLE_EQ(distance({ 1, 1 }, { { 0, 0 }, { 2, 0 } }), 1.0);
	EXPECT_DOUBLE_EQ(distance({ 3, 0 }, { { 0, 0 }, { 2, 0 } }), 1.0);
}

TEST(JointSet, PersistentSetCutsTheBoxAtItsSpacing)
{
	JointSet s;
	s.origin  = { 0, 0 };
	s.dipDeg  = 0; // horizontal joints y = k
	s.spacing = 1;
	Box box;
	box.extend({ -0.5, 0.5 });
	box.extend({ 3, 4.2 });
	const auto joints = s.segments(box);
	ASSERT_EQ(joints.size(), 4u); // y = 1, 2, 3, 4
	for (size_t k = 0; k < joints.size(); ++k) {
		EXPECT_NEAR(joints[k].a.y, double(k + 1), 1e-12);
		EXPECT_NEAR(std::abs(joints[k].b.x - joints[k].a.x), 3.5, 1e-12);
	}
	EXPECT_EQ(s.band({ 0, 2.5 }), 2);
	EXPECT_EQ(s.band({ 0, -0.5 }), -1);
}

TEST(JointSet, DippingSetNormalAndBands)
{
	JointSet s;
	s.dipDeg  = 45;
	s.spacing = std::sqrt(2.0);
	EXPECT_NEAR(s.normal().x, -std::sqrt(0.5), 1e-12);
	EXPECT_NEAR(dot(s.normal(), s.direction()), 0, 1e-12);
	// Lines y = x + 2k; the point (0, 3) lies between y = x + 2 and y = x + 4.
	EXPECT_EQ(s.band({ 0, 3 }), 1);
}

TEST(JointSet, PersistenceLeavesRockBridges)
{
	JointSet s;
	s.dipDeg       = 0;
	s.spacing      = 10;
	s.jointLength  = 3;
	s.bridgeLength = 1;
	Box box;
	box.extend({ 0, -1 });
	box.extend({ 16, 1 });
	const auto joints = s.segments(box); // y = 0: [0,3] [4,7] [8,11] [12,15]
	ASSERT_EQ(joints.size(), 4u);
	double length = 0;
	for (const Segment& j : joints)
		length += norm(j.b - j.a);
	EXPECT_DOUBLE_EQ(length, 12.0);
	EXPECT_DOUBLE_EQ(s.persistence(), 0.75);
	EXPECT_NEAR(joints[1].a.x, 4.0, 1e-12);
}

TEST(JointSet, InvalidSpacingIsRejected)
{
	JointSet s;
	s.spacing = -1;
	EXPECT_THROW(s.segments(Box {}), std::invalid_argument);
}

TEST(JointSet, EveryAttributeOutsideItsRangeIsRejectedByName)
{
	const auto message = [](auto change) {
		JointSet s;
		change(s);
		try {
			s.validate();
		} catch (const std::invalid_argument& e) {
			return std::string(e.what());
		}
		return std::string();
	};
	EXPECT_EQ(message([](JointSet& s) { s.dipDeg = 200; }).rfind("dip = 200 is invalid: it must be in [-180, 180] deg", 0), 0u);
	EXPECT_EQ(message([](JointSet& s) { s.jointLength = 0; }).rfind("jointLength = 0 is invalid", 0), 0u);
	EXPECT_EQ(message([](JointSet& s) { s.bridgeLength = -1; }).rfind("bridgeLength = -1 is invalid", 0), 0u);
	EXPECT_EQ(message([](JointSet& s) { s.origin.x = std::nan(""); }).rfind("origin = nan is invalid", 0), 0u);
	EXPECT_EQ(message([](JointSet& s) { s.dipDeg = -20; }), "");
}

TEST(BlockIndex, TwoSetsMakeRectangularBlocks)
{
	JointSet vertical, horizontal;
	vertical.dipDeg    = 90;
	vertical.spacing   = 1;
	horizontal.dipDeg  = 0;
	horizontal.spacing = 2;
	BlockIndex blocks({ vertical, horizontal });
	const int  a = blocks.blockId({ 0.5, 0.5 });
	EXPECT_EQ(blocks.blockId({ 0.9, 1.9 }), a);
	EXPECT_NE(blocks.blockId({ 1.1, 0.5 }), a);
	EXPECT_NE(blocks.blockId({ 0.5, 2.1 }), a);
}

TEST(CrossedSegment, IsTheJointTheCentreLineCrosses)
{
	const std::vector<Segment> joints { { { 0, 1 }, { 10, 1 } }, { { 0, 2 }, { 10, 2 } } };
	EXPECT_EQ(crossedSegment(joints, { 1, 1.5 }, { 1, 2.5 }), &joints[1]);
	EXPECT_EQ(crossedSegment(joints, { 1, 0.5 }, { 1, 1.5 }), &joints[0]);
	EXPECT_EQ(crossedSegment(joints, { 11, 0 }, { 11, 3 }), nullptr);
}

TEST(Facing, IsTheDistanceToTheNearestJointOnEachSideWithinReach)
{
	const std::vector<Segment> joints { { { 0, 1 }, { 10, 1 } }, { { 0, 2 }, { 10, 2 } }, { { 0, 3 }, { 10, 3 } } };
	const auto                 between = facing(joints, { 5, 1.8 }, { 0, 1 }, 1.0);
	EXPECT_DOUBLE_EQ(between[1], 0.8);   // above the joint at y = 1
	EXPECT_NEAR(between[0], 0.2, 1e-12); // below the one at y = 2
	const auto beyond = facing(joints, { 11, 1.8 }, { 0, 1 }, 1.0);
	EXPECT_TRUE(std::isinf(beyond[0]) && std::isinf(beyond[1]));           // past the joints' ends
	EXPECT_TRUE(std::isinf(facing(joints, { 5, 4.5 }, { 0, 1 }, 1.0)[1])); // out of reach
}
