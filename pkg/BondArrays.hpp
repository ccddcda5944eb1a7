// A parallel bond's state held contiguously (the disc path's array of bonds) rather than in its
// scattered ParallelBondPhys: the same members under the same names, so that the parallel-bond
// law runs the same arithmetic on either. The physics object stays the record YADE and Python
// see; DiscInteractionLoop copies an entry into it (store) wherever something else may read it.
#pragma once

#include "ParallelBond.hpp"
#include <core/Interaction.hpp>
#include <pkg/dem/ScGeom.hpp>

// Every ParallelBondPhys member the law reads or writes, named once for both copies.
// clang-format off
#define TOPPLING_BOND_MEMBERS(X)                                                                                       \
	X(contactKn) X(contactKs) X(contactDamping) X(contactNormalForce) X(contactShearForce) X(isSlipping)           \
	X(tangensOfFrictionAngle) X(bondState) X(bondRadius) X(bondArea) X(bondInertia) X(bondKn) X(bondKs)            \
	X(bondDamping) X(bondTensileStrength) X(bondCohesion) X(bondTanFriction) X(bondRefOverlap) X(bondNormalForce)  \
	X(bondShearForce) X(bondMoment) X(bondSigmaMax) X(bondTauMax) X(normalBefore) X(normalForce) X(shearForce)
// clang-format on

namespace yade {
namespace toppling {

	// What the law reads of a disc pair's geometry, formed from the two discs' centres and radii.
	struct DiscContact {
		Real     penetrationDepth;
		Vector3r normal, contactPoint;
		Real     refR1, refR2;
	};

	struct BondEntry {
		Interaction*      interaction;
		ParallelBondPhys* phys;
		Real              contactKn, contactKs, contactDamping, contactNormalForce;
		Vector3r          contactShearForce;
		bool              isSlipping;
		Real              tangensOfFrictionAngle;
		int               bondState;
		Real     bondRadius, bondArea, bondInertia, bondKn, bondKs, bondDamping, bondTensileStrength, bondCohesion, bondTanFriction, bondRefOverlap;
		Real     bondNormalForce;
		Vector3r bondShearForce;
		Real     bondMoment, bondSigmaMax, bondTauMax;
		Vector3r normalBefore, normalForce, shearForce;
		Real     refR1, refR2; // the geometry's reference radii

		BondEntry(Interaction& I)
		        : interaction(&I)
		        , phys(static_cast<ParallelBondPhys*>(I.phys.get()))
		{
			const auto& geom = static_cast<const ScGeom&>(*I.geom);
			refR1            = geom.refR1;
			refR2            = geom.refR2;
#define TOPPLING_LOAD(m) m = phys->m;
			TOPPLING_BOND_MEMBERS(TOPPLING_LOAD)
#undef TOPPLING_LOAD
		}
		void store() const
		{
#define TOPPLING_STORE(m) phys->m = m;
			TOPPLING_BOND_MEMBERS(TOPPLING_STORE)
#undef TOPPLING_STORE
		}
		bool isBonded() const { return bondState == ParallelBondPhys::intact; }
		// A bond's energy and its end go through the physics object, which also holds the total stiffness.
		Real bondEnergy() const
		{
			store();
			return phys->bondEnergy();
		}
		void setBondState(int state)
		{
			phys->setBondState(state);
			bondState       = state;
			bondNormalForce = 0;
			bondShearForce  = Vector3r::Zero();
			bondMoment      = 0;
		}
	};

} // namespace toppling
} // namespace yade
