// The small pieces every toppling contact law is assembled from (linear spring, viscous
// dashpot, Coulomb slider). Written once here so that the parallel-bond law and the
// smooth-joint law cannot drift apart.
#pragma once

#include <lib/base/Math.hpp>
#include <core/Body.hpp>
#include <core/ForceContainer.hpp>
#include <core/State.hpp>
#ifdef YADE_OPENMP
#include <omp.h>
#endif

namespace yade {
namespace toppling {

	// Two linear springs in series, e.g. the two discs' stiffnesses of a contact.
	inline Real seriesStiffness(Real k1, Real k2) { return k1 * k2 / (k1 + k2); }

	// Mass seen by a dashpot between two bodies; a body that is not dynamic (a wall, a fixed
	// disc) behaves as infinitely heavy.
	inline Real effectiveMass(const Body& b1, const Body& b2)
	{
		const bool d1 = b1.isDynamic(), d2 = b2.isDynamic();
		if (d1 && d2) return b1.state->mass * b2.state->mass / (b1.state->mass + b2.state->mass);
		if (d1) return b1.state->mass;
		if (d2) return b2.state->mass;
		return 0;
	}

	// Dashpot coefficient for critical damping ratio beta of a spring k carrying mass m:
	// c = 2 beta sqrt(m k).
	inline Real dashpotCoefficient(Real beta, Real mass, Real k) { return 2 * beta * math::sqrt(mass * k); }

	// How many bodies or pairs ahead the disc path asks for the memory it will read: enough to
	// cover a load from memory with the work of the ones between.
	constexpr long prefetchAhead = 8;

	// What a law reads of a body's motion: a copy of its State's (the disc path gathers them for
	// every body once per step, contiguous, rather than from every pair's two State objects).
	struct Kinematics {
		Vector3r pos, vel, angVel;
		Kinematics() = default;
		explicit Kinematics(const State& s)
		        : pos(s.pos)
		        , vel(s.vel)
		        , angVel(s.angVel)
		{
		}
	};

	// Relative velocity of body 2's contact point with respect to body 1's.
	inline Vector3r relativeVelocity(const Kinematics& s1, const Kinematics& s2, const Vector3r& contactPoint)
	{
		return (s2.vel + s2.angVel.cross(contactPoint - s2.pos)) - (s1.vel + s1.angVel.cross(contactPoint - s1.pos));
	}

	// Component of v orthogonal to the unit vector n.
	inline Vector3r tangential(const Vector3r& v, const Vector3r& n) { return v - v.dot(n) * n; }

	// The smaller of two radii; a non-positive radius (a wall) does not count.
	inline Real smallerRadius(Real r1, Real r2) { return (r1 > 0 && r2 > 0) ? math::min(r1, r2) : math::max(r1, r2); }

	// A stable explicit DEM step moves contacting bodies by a small fraction of their size; a
	// relative displacement of a tenth of the smaller radius in one step means the time step is
	// far too large (the run is blowing up). Non-positive radii (walls) are ignored.
	template <class Vector> inline bool stepIsSmall(const Vector& relativeVelocity, Real dt, Real r1, Real r2)
	{
		const Real r  = smallerRadius(r1, r2);
		const Real d2 = relativeVelocity.squaredNorm() * dt * dt;
		return math::isfinite(d2) && (r <= 0 || d2 < 0.01 * r * r);
	}

	// Coulomb slider: scales the shear force back onto |Fs| <= limit; true while slipping. (In the
	// plane a Vector2r gives the same doubles as a Vector3r with z = 0.)
	template <class Vector> inline bool coulombSlip(Vector& shearForce, Real limit)
	{
		const Real fs = shearForce.norm();
		if (fs <= limit) return false;
		shearForce *= (fs > 0 ? limit / fs : 0);
		return true;
	}

	// Coulomb slider with dilation in a joint's own frame (normal force fn = knA * overlap,
	// compression positive; scalar shear force fs): beyond the limit tanPhi * fn the shear force
	// returns to it, and the plastic slip (|fs| - limit) / ksA closes the joint by slip * tanPsi
	// (dilation against the confinement), raising fn. Returns the plastic slip (0 while sticking).
	inline Real dilatantSlip(Real& fn, Real& fs, Real& overlap, Real knA, Real ksA, Real tanPhi, Real tanPsi)
	{
		const Real limit = tanPhi * fn;
		if (math::abs(fs) <= limit) return 0;
		const Real slip = (math::abs(fs) - limit) / ksA;
		overlap += slip * tanPsi;
		fn = knA * overlap;
		fs = (fs < 0 ? -1 : 1) * tanPhi * fn;
		return slip;
	}

	// Forces and torques summed per thread and body during one interaction loop, then added to
	// YADE's ForceContainer once per body: its every add writes a flag shared by all threads.
	// Summed in the order the laws add them, from zero, the totals are those the container would
	// hold (it starts each step at zero and sums its per-thread buffers the same way).
	class ForceSums {
	public:
		void reset(int threads, size_t bodies)
		{
			force.resize(threads);
			torque.resize(threads);
			for (int t = 0; t < threads; ++t) {
				force[t].assign(bodies, Vector3r::Zero());
				torque[t].assign(bodies, Vector3r::Zero());
			}
		}
		// f on body 1, -f on body 2, torques t1 and t2 (one thread lookup for the four)
		void addPair(Body::id_t id1, Body::id_t id2, const Vector3r& f, const Vector3r& t1, const Vector3r& t2)
		{
			const int t = thread();
			force[t][id1] += f;
			force[t][id2] += -f;
			torque[t][id1] += t1;
			torque[t][id2] += t2;
		}
		// The sums' entries of a pair soon to be added to, fetched ahead (their order in memory is
		// the bodies', not the pairs').
		void prefetchPair(Body::id_t id1, Body::id_t id2) const
		{
			const int t = thread();
			__builtin_prefetch(&force[t][id1], 1), __builtin_prefetch(&force[t][id2], 1);
			__builtin_prefetch(&torque[t][id1], 1), __builtin_prefetch(&torque[t][id2], 1);
		}
		void addTo(ForceContainer& forces) const
		{
			for (size_t t = 0; t < force.size(); ++t)
				for (size_t id = 0; id < force[t].size(); ++id) {
					forces.addForce(Body::id_t(id), force[t][id]);
					forces.addTorque(Body::id_t(id), torque[t][id]);
				}
		}

	private:
		std::vector<std::vector<Vector3r>> force, torque;
		static int                         thread()
		{
#ifdef YADE_OPENMP
			return omp_get_thread_num();
#else
			return 0;
#endif
		}
	};

	// One addForce and one addTorque per body: every call writes a flag shared by all threads in
	// YADE's ForceContainer, so fewer calls scale better.
	inline void addPair(ForceContainer& forces, Body::id_t id1, Body::id_t id2, const Vector3r& f, const Vector3r& t1, const Vector3r& t2)
	{
		forces.addForce(id1, f);
		forces.addForce(id2, -f);
		forces.addTorque(id1, t1);
		forces.addTorque(id2, t2);
	}
	inline void addPair(ForceSums& sums, Body::id_t id1, Body::id_t id2, const Vector3r& f, const Vector3r& t1, const Vector3r& t2)
	{
		sums.addPair(id1, id2, f, t1, t2);
	}

	// Applies force f on body 1 (-f on body 2) at the contact point and a couple m on body 2 (-m on
	// body 1).
	template <class Forces>
	inline void applyContact(
	        Forces&         forces,
	        Body::id_t      id1,
	        const Vector3r& pos1,
	        Body::id_t      id2,
	        const Vector3r& pos2,
	        const Vector3r& point,
	        const Vector3r& f,
	        const Vector3r& m)
	{
		addPair(forces, id1, id2, f, (point - pos1).cross(f) - m, -(point - pos2).cross(f) + m);
	}

	// The turn of the contact frame over one step, as ScGeom::precompute forms it from the
	// normals before and now and the pair's mean spin about the normal: a shear force carried
	// over from the last step is turned with turn(); the same arithmetic as ScGeom::rotate.
	struct FrameTurn {
		Vector3r tilt, twist;
		FrameTurn(const Vector3r& before, const Vector3r& now, const Vector3r& spin1, const Vector3r& spin2, Real dt)
		        : tilt(before.cross(now))
		        , twist((dt * 0.5 * before.dot(spin1 + spin2)) * before)
		{
		}
		__attribute__((always_inline)) Vector3r& turn(Vector3r& shear) const
		{
			shear -= shear.cross(tilt);
			shear -= shear.cross(twist);
			return shear;
		}
	};

	// Elastic energy of a linear spring holding force f.
	inline Real springEnergy(Real f, Real k) { return k > 0 ? 0.5 * f * f / k : 0; }

} // namespace toppling
} // namespace yade
