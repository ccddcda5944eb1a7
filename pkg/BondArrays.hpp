// A parallel bond between two discs moving in the xy-plane, held contiguously in the disc path's
// array rather than in its scattered ParallelBondPhys, its vectors by their x and y components
// (in the plane the others are zero). The physics object stays the record YADE and Python see:
// DiscInteractionLoop copies the entry into it (store) wherever something else may read it.
#pragma once

#include "ParallelBond.hpp"
#include <core/Interaction.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {
namespace toppling {

	// Two discs' contact in the plane, as DiscInteractionLoop::updateDiscPair forms it in space.
	struct PlaneContact {
		Vector2r normal, point, relativeVelocity; // body 1 to body 2; body 2's point's velocity relative to body 1's
		Real     overlap;
		Real     z; // the plane's
	};

	struct DiscBond {
		// carried from step to step
		Vector2r normalBefore;            // ParallelBondPhys.normalBefore
		Real     fcn;                     // contactNormalForce
		Vector2r fcs;                     // contactShearForce
		Real     fbn;                     // bondNormalForce
		Vector2r fbs;                     // bondShearForce
		Real     moment;                  // bondMoment
		int      state;                   // bondState
		bool     slipping;                // isSlipping
		Vector2r normalForce, shearForce; // the total force on body 2
		Real     sigmaMax, tauMax;        // bondSigmaMax, bondTauMax
		// constants (a change from Python is taken in when the array is built again)
		Real              kn, ks, tanPhi, contactDamping, bondDamping; // contact
		Real              knA, ksA, knI, area, inertia, radius, refOverlap, tensileStrength, cohesion, tanPhiBond;
		Real              refR1, refR2; // the geometry's reference radii
		Interaction*      interaction;
		ParallelBondPhys* phys;

		explicit DiscBond(Interaction& I)
		        : interaction(&I)
		        , phys(static_cast<ParallelBondPhys*>(I.phys.get()))
		{
			const ParallelBondPhys& p    = *phys;
			const auto&             geom = static_cast<const ScGeom&>(*I.geom);
			normalBefore = p.normalBefore.head<2>(), fcn = p.contactNormalForce, fcs = p.contactShearForce.head<2>();
			fbn = p.bondNormalForce, fbs = p.bondShearForce.head<2>(), moment = p.bondMoment;
			state = p.bondState, slipping = p.isSlipping;
			normalForce = p.normalForce.head<2>(), shearForce = p.shearForce.head<2>();
			sigmaMax = p.bondSigmaMax, tauMax = p.bondTauMax;
			kn = p.contactKn, ks = p.contactKs, tanPhi = p.tangensOfFrictionAngle, contactDamping = p.contactDamping;
			bondDamping = p.bondDamping;
			// as the law forms them: (k A) x, so the same products
			knA = p.bondKn * p.bondArea, ksA = p.bondKs * p.bondArea, knI = p.bondKn * p.bondInertia;
			area = p.bondArea, inertia = p.bondInertia, radius = p.bondRadius, refOverlap = p.bondRefOverlap;
			tensileStrength = p.bondTensileStrength, cohesion = p.bondCohesion, tanPhiBond = p.bondTanFriction;
			refR1 = geom.refR1, refR2 = geom.refR2;
		}
		void store() const
		{
			ParallelBondPhys& p  = *phys;
			p.normalBefore       = inSpace(normalBefore);
			p.contactNormalForce = fcn, p.contactShearForce = inSpace(fcs);
			p.bondNormalForce = fbn, p.bondShearForce = inSpace(fbs), p.bondMoment = moment;
			p.bondState = state, p.isSlipping = slipping;
			p.normalForce = inSpace(normalForce), p.shearForce = inSpace(shearForce);
			p.bondSigmaMax = sigmaMax, p.bondTauMax = tauMax;
		}
		static Vector3r inSpace(const Vector2r& v) { return Vector3r(v.x(), v.y(), 0); }
		bool            isBonded() const { return state == ParallelBondPhys::intact; }
	};

} // namespace toppling
} // namespace yade
