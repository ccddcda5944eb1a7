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

	struct DiscBond {
		// carried from step to step
		Real nx0, ny0;                // ParallelBondPhys.normalBefore
		Real fcn, fcsx, fcsy;         // contactNormalForce, contactShearForce
		Real fbn, fbsx, fbsy, moment; // bondNormalForce, bondShearForce, bondMoment
		int  state;                   // bondState
		bool slipping;                // isSlipping
		Real fnx, fny, fsx, fsy;      // normalForce, shearForce
		Real sigmaMax, tauMax;        // bondSigmaMax, bondTauMax
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
			nx0 = p.normalBefore.x(), ny0 = p.normalBefore.y();
			fcn = p.contactNormalForce, fcsx = p.contactShearForce.x(), fcsy = p.contactShearForce.y();
			fbn = p.bondNormalForce, fbsx = p.bondShearForce.x(), fbsy = p.bondShearForce.y(), moment = p.bondMoment;
			state = p.bondState, slipping = p.isSlipping;
			fnx = p.normalForce.x(), fny = p.normalForce.y(), fsx = p.shearForce.x(), fsy = p.shearForce.y();
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
			p.normalBefore       = Vector3r(nx0, ny0, 0);
			p.contactNormalForce = fcn, p.contactShearForce = Vector3r(fcsx, fcsy, 0);
			p.bondNormalForce = fbn, p.bondShearForce = Vector3r(fbsx, fbsy, 0), p.bondMoment = moment;
			p.bondState = state, p.isSlipping = slipping;
			p.normalForce = Vector3r(fnx, fny, 0), p.shearForce = Vector3r(fsx, fsy, 0);
			p.bondSigmaMax = sigmaMax, p.bondTauMax = tauMax;
		}
		bool isBonded() const { return state == ParallelBondPhys::intact; }
	};

} // namespace toppling
} // namespace yade
