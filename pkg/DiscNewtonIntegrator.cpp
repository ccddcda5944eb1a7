#include "DiscNewtonIntegrator.hpp"
#include "DiscInteractionLoop.hpp"
#include <core/Scene.hpp>

namespace yade {

YADE_PLUGIN((DiscNewtonIntegrator));

void DiscNewtonIntegrator::action()
{
	DiscInteractionLoop* loop = nullptr;
	for (const auto& e : scene->engines)
		if (auto* l = dynamic_cast<DiscInteractionLoop*>(e.get())) loop = l;
	const bool lean = loop && loop->arraysThisStep && covers(*loop);
	if (loop) loop->arraysThisStep = false; // this step's
	if (lean) integrate(*loop);
	else {
		if (loop) loop->settleOrientations();
		NewtonIntegrator::action();
	}
}

// Whether this step is one the lean integration covers; the bodies' constants are taken again
// whenever the loop built its array again (Python may have changed them, or the collider the bounds).
bool DiscNewtonIntegrator::covers(const DiscInteractionLoop& loop)
{
#ifdef YADE_BODY_CALLBACK
	if (!callbacks.empty()) return false;
#endif
	if (scene->isPeriodic || scene->trackEnergy || mask > 0 || densityScaling || !dampGravity) return false;
	if (builtWith != loop.builds) {
		coversBodies = takeConstants();
		builtWith    = loop.builds;
	}
	return coversBodies;
}

// Every body's constants; false if a body is one NewtonIntegrator treats otherwise (a clump, a
// body it turns as aspherical).
bool DiscNewtonIntegrator::takeConstants()
{
	bodies.assign(scene->bodies->size(), Constants());
	for (const auto& b : *scene->bodies) {
		if (!b) continue;
		const State& s = *b->state;
		if (b->isClump() || b->isClumpMember() || (exactAsphericalRot && b->isAspherical() && (s.blockedDOFs & State::DOF_RXRYRZ) == State::DOF_NONE))
			return false;
		Constants& c = bodies[b->id];
		c.state      = b->state.get();
		c.mass       = s.mass;
		c.inertia    = s.inertia;
		c.blocked    = s.blockedDOFs;
		c.damped     = s.isDamped;
		c.planar     = (!b->isDynamic() || (s.blockedDOFs & (State::DOF_RX | State::DOF_RY)) == (State::DOF_RX | State::DOF_RY)) && s.angVel.x() == 0
		        && s.angVel.y() == 0;
		c.bounded = bool(b->bound);
		if (c.bounded) c.refPos = b->bound->refPos, c.sweepLength = b->bound->sweepLength;
	}
	return true;
}

// NewtonIntegrator::action's arithmetic for a standalone sphere, body by body.
void DiscNewtonIntegrator::integrate(DiscInteractionLoop& loop)
{
	scene->forces.sync();
	const Real dt  = scene->dt;
	const long n   = long(bodies.size());
	Real       max = 0; // the bodies' largest displacement, as NewtonIntegrator::maxVelocitySq holds it
#ifdef YADE_OPENMP
#pragma omp parallel for reduction(max : max) num_threads(ompThreads > 0 ? std::min(ompThreads, omp_get_max_threads()) : omp_get_max_threads())
#endif
	for (long id = 0; id < n; ++id) {
		if (id + toppling::prefetchAhead < n) prefetchState(bodies[id + toppling::prefetchAhead].state);
		const Constants& c = bodies[id];
		if (!c.state) continue;
		State& s = *c.state;
		if (c.blocked != State::DOF_ALL) {
			s.vel += dt * linearAcceleration(scene->forces.getForce(id), c, s.vel);
			s.angVel += dt * angularAcceleration(scene->forces.getTorque(id), c, s.angVel);
		}
		s.pos += s.vel * dt;
		if (c.planar) loop.turn[id] += s.angVel.z() * dt;
		else { // NewtonIntegrator::leapfrogSphericalRotate
			const Real angle2 = s.angVel.squaredNorm();
			if (angle2 != 0) {
				const Real angle = sqrt(angle2);
				s.ori            = Quaternionr(AngleAxisr(angle * dt, s.angVel / angle)) * s.ori;
			}
			s.ori.normalize();
		}
		if (c.bounded) { // NewtonIntegrator::saveMaximaDisplacement
			const Vector3r disp    = s.pos - c.refPos;
			const Real     maxDisp = math::max(math::abs(disp[0]), math::max(math::abs(disp[1]), math::abs(disp[2])));
			max                    = math::max(max, (!maxDisp || maxDisp < c.sweepLength) ? Real(0.5) : Real(2));
		}
		loop.motion[id] = toppling::Kinematics(s);
	}
	maxVelocitySq    = max;
	loop.motionFresh = loop.turnPending = true;
	if (loop.lastReader == DiscInteractionLoop::Reader::any) loop.settleOrientations();
}

// Asks for the lines of a body's State the step reads and writes (position, orientation, both
// velocities), a few bodies early: a loaded scene's State objects lie anywhere in memory.
void DiscNewtonIntegrator::prefetchState(const State* s)
{
	if (!s) return;
	__builtin_prefetch(s, 1);
	const char* motion = reinterpret_cast<const char*>(&s->se3);
	__builtin_prefetch(motion, 1), __builtin_prefetch(motion + 64, 1);
	__builtin_prefetch(reinterpret_cast<const char*>(&s->angVel + 1) - 1, 1);
}

// NewtonIntegrator::computeAccel and cundallDamp2nd.
Vector3r DiscNewtonIntegrator::linearAcceleration(const Vector3r& f, const Constants& c, const Vector3r& vel) const
{
	Vector3r a;
	if (c.blocked == 0) a = f / c.mass + gravity;
	else {
		a = Vector3r::Zero();
		for (int i = 0; i < 3; i++)
			if (!(c.blocked & State::axisDOF(i, false))) a[i] += f[i] / c.mass + gravity[i];
	}
	if (c.damped)
		for (int i = 0; i < 3; i++)
			a[i] *= 1 - damping * math::sign(a[i] * (vel[i] + 0.5 * scene->dt * a[i]));
	return a;
}

// NewtonIntegrator::computeAngAccel and cundallDamp2nd.
Vector3r DiscNewtonIntegrator::angularAcceleration(const Vector3r& m, const Constants& c, const Vector3r& angVel) const
{
	Vector3r a;
	if (c.blocked == 0) a = m.cwiseQuotient(c.inertia);
	else {
		a = Vector3r::Zero();
		for (int i = 0; i < 3; i++)
			if (!(c.blocked & State::axisDOF(i, true))) a[i] += m[i] / c.inertia[i];
	}
	if (c.damped)
		for (int i = 0; i < 3; i++)
			a[i] *= 1 - damping * math::sign(a[i] * (angVel[i] + 0.5 * scene->dt * a[i]));
	return a;
}

} // namespace yade
