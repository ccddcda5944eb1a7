// NewtonIntegrator for a disc scene stepped by DiscInteractionLoop::runSteps: while the loop holds
// its bonds in the array, each body's constants are read from an array built with it, and the
// bodies' new motion is written to the loop's arrays as well as to their State, so that the next
// loop needs not gather it. The same arithmetic as NewtonIntegrator (spheres, not periodic, no
// clumps, no energy tracking, no mask, no density scaling, gravity damped), but for a disc's
// orientation: its turns about z are summed and applied to State.ori at once when something may
// read it (equal to round-off). Anything else, and any step outside runSteps, runs
// NewtonIntegrator itself.
#pragma once

#include <pkg/dem/NewtonIntegrator.hpp>

namespace yade {

class DiscInteractionLoop;

class DiscNewtonIntegrator : public NewtonIntegrator {
public:
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC(DiscNewtonIntegrator, NewtonIntegrator,
		"A :yref:`NewtonIntegrator` for disc scenes run by :yref:`DiscInteractionLoop.runSteps`: the same results "
		"(a disc's :yref:`State.ori` to round-off: its turns about z are applied at once when something may read it), "
		"without reading each body's constants from its objects and with the new motion handed to the loop. "
		"Outside such runs, or for a scene it does not cover (clumps, periodic cell, energy tracking, ``mask``, "
		"density scaling, ``dampGravity`` off, aspherical rotation), it is NewtonIntegrator.");
	// clang-format on

private:
	struct Constants {                // one per body id, as its State held them when the loop's array was built
		State*   state = nullptr; // null: no body
		Real     mass  = 0;
		Vector3r inertia, refPos;
		Real     sweepLength = 0;
		unsigned blocked     = 0;
		bool     damped = false, bounded = false;
		bool     planar = false; // turns about z only: its orientation can wait (DiscInteractionLoop::turn)
	};
	std::vector<Constants> bodies;
	long                   builtWith    = -1;    // the loop's build this array was made with
	bool                   coversBodies = false; // every body is one integrate() covers
	bool                   covers(const DiscInteractionLoop& loop);
	bool                   takeConstants();
	void                   integrate(DiscInteractionLoop& loop);
	static void            prefetchState(const State* s);
	Vector3r               linearAcceleration(const Vector3r& f, const Constants& c, const Vector3r& vel) const;
	Vector3r               angularAcceleration(const Vector3r& m, const Constants& c, const Vector3r& angVel) const;
};
REGISTER_SERIALIZABLE(DiscNewtonIntegrator);

} // namespace yade
