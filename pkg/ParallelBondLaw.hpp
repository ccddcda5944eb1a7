// The parallel-bond law (Potyondy & Cundall 2004, PFC2D form): contact and bond forces, the
// bond's failure, and the scene-wide queries built on them (energy, bond counts, time step).
#pragma once

#include "BondArrays.hpp"
#include "BreakingLaw.hpp"
#include "ContactPieces.hpp"
#include "ParallelBond.hpp"
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Law2_ScGeom_ParallelBondPhys_ParallelBond : public BreakingLaw {
public:
	bool go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I) override;
	// go() on the two bodies' kinematics, as given (DiscInteractionLoop gathers them).
	bool interact(const Interaction& I, ScGeom& geom, ParallelBondPhys& phys, const toppling::Kinematics& b1, const toppling::Kinematics& b2);
	// The same for two discs in the xy-plane, on a bond held in the disc path's array (its physics
	// object is not touched unless it breaks; the forces go to `sums`).
	bool
	interact(toppling::DiscBond& bond, Body::id_t id1, Body::id_t id2, const toppling::Kinematics& b1, const toppling::Kinematics& b2, Real r1, Real r2);
	Real elasticEnergy() const;
	int  countBonds(int state) const;
	Real criticalTimeStep() const;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Law2_ScGeom_ParallelBondPhys_ParallelBond, BreakingLaw,
		"Parallel-bond law (Potyondy & Cundall 2004, PFC2D). Contact: $F_n=k_nu_n$ for $u_n>0$, incremental shear "
		"(from the contact point's relative velocity, rotated with the contact frame), $|F_s|\\le\\mu F_n$. Bond: "
		"$\\bar F_n=\\bar k^nA(u_n-u_{n,0})$, $\\Delta\\bar F_s=-\\bar k^sA\\Delta u_s$, $\\Delta\\bar M=-\\bar k^nI\\Delta\\theta_z$. "
		"It breaks in tension when $\\bar\\sigma_{max}=-\\bar F_n/A+|\\bar M|\\bar R/I\\ge\\bar\\sigma_c$, else in shear when "
		"$|\\bar F_s|/A\\ge\\bar c+\\sigma\\tan\\bar\\phi$ ($\\sigma=\\bar F_n/A$); the contact then goes on as frictional "
		"and the break is recorded (see :yref:`BreakingLaw`). Dashpots $c\\,v_n$ act while touching (contact) and "
		"while bonded (bond).",
		/*attrs*/,
		/*ctor*/,
		.def("elasticEnergy", &Law2_ScGeom_ParallelBondPhys_ParallelBond::elasticEnergy,
			"Elastic energy in all contacts and bonds of this law [J].")
		.def("criticalTimeStep", &Law2_ScGeom_ParallelBondPhys_ParallelBond::criticalTimeStep,
			"Critical time step from the stiffness of every contact, bond and smooth joint, loaded or not [s]: "
			":yref:`GlobalStiffnessTimeStepper`'s estimate (safety 1), which skips interactions carrying no force "
			"and so misses freshly installed, stress-free bonds. ``toppling.build.bonding`` uses it after bonding.")
		.def("countBonds", &Law2_ScGeom_ParallelBondPhys_ParallelBond::countBonds, (boost::python::arg("state") = 1),
			"Number of interactions whose :yref:`ParallelBondPhys.bondState` equals ``state``.")
	);
	// clang-format on
	FUNCTOR2D(ScGeom, ParallelBondPhys);

private:
	bool updateBond(
	        const Interaction&         I,
	        const ScGeom&              geom,
	        ParallelBondPhys&          phys,
	        const toppling::FrameTurn& frame,
	        const Vector3r&            shearIncrement,
	        Real                       relativeSpin);
	void breakBond(toppling::DiscBond& bond, const toppling::PlaneContact& contact, int mode);
};
REGISTER_SERIALIZABLE(Law2_ScGeom_ParallelBondPhys_ParallelBond);

} // namespace yade
