// Parallel-bond model for discs (Potyondy & Cundall 2004, PFC2D form): a linear frictional
// contact in parallel with an elastic-brittle bond that carries force and moment. Material,
// physics and the Ip2 that decides rock or joint; the law is ParallelBondLaw.hpp.
#pragma once

#include "BreakingLaw.hpp"
#include "JointSystem.hpp"
#include <lib/base/AliasNamespaces.hpp>
#include <core/Dispatching.hpp>
#include <pkg/common/ElastMat.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <limits>

namespace yade {

class ParallelBondMat : public FrictMat {
public:
	void validate() const;
	void postLoad(ParallelBondMat&) { validate(); }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR(ParallelBondMat, FrictMat,
		"Rock as bonded discs (Potyondy & Cundall 2004, PFC2D). Bodies are spheres moving in the xy-plane "
		"(``blockedDOFs='zXY'``) and stand for discs of thickness :yref:`thickness<ParallelBondMat.thickness>`.\n\n"
		"Contact: each disc is a normal spring $k = 2tE_c$ (``young`` is $E_c$ [Pa]); the two discs of a contact act "
		"in series, $k_n = k^{[1]}k^{[2]}/(k^{[1]}+k^{[2]})$ ($=tE_c$ for one material), $k_s = k_n/(k_n/k_s)$; no tension, "
		"Coulomb friction $\\mu=\\tan$ ``frictionAngle``.\n\n"
		"Bond (installed by :yref:`ParallelBondPhys.installBond`): $\\bar R = \\bar\\lambda\\min(R_1,R_2)$, $A=2\\bar Rt$, "
		"$I=\\tfrac23\\bar R^3t$, $\\bar k^n = \\bar E_c/(R_1+R_2)$, $\\bar k^s=\\bar k^n/(\\bar k^n/\\bar k^s)$ [N/m³].\n\n"
		"Two materials: disc stiffnesses in series, stiffness ratios averaged, bond modulus, strengths, thickness "
		"and friction angles the smaller value, damping ratios the larger.",
		((Real, knKs, 1, Attr::triggerPostLoad, "Contact normal-to-shear stiffness ratio $k_n/k_s$ [-] (> 0)."))
		((Real, thickness, 1, Attr::triggerPostLoad, "Disc thickness $t$ [m] (> 0); also sets disc mass $\\rho\\pi R^2t$ when discs are made by ``toppling.build.discs.disc``."))
		((Real, normalDamping, 0, Attr::triggerPostLoad, "Contact normal critical damping ratio $\\beta_n$ [-], in [0,1)."))
		((Real, bondRadiusMultiplier, 1, Attr::triggerPostLoad, "Bond radius multiplier $\\bar\\lambda$ [-] (> 0)."))
		((Real, bondYoung, 1e9, Attr::triggerPostLoad, "Bond modulus $\\bar E_c$ [Pa] (>= 0)."))
		((Real, bondKnKs, 1, Attr::triggerPostLoad, "Bond normal-to-shear stiffness ratio $\\bar k^n/\\bar k^s$ [-] (> 0)."))
		((Real, bondTensileStrength, std::numeric_limits<Real>::infinity(), Attr::triggerPostLoad, "Bond tensile strength $\\bar\\sigma_c$ [Pa] (>= 0)."))
		((Real, bondCohesion, std::numeric_limits<Real>::infinity(), Attr::triggerPostLoad, "Bond cohesion $\\bar c$ [Pa] (>= 0)."))
		((Real, bondFrictionAngle, 0, Attr::triggerPostLoad, "Bond friction angle $\\bar\\phi$ [rad], in [0, π/2)."))
		((Real, bondNormalDamping, 0, Attr::triggerPostLoad, "Bond normal critical damping ratio $\\bar\\beta_n$ [-], in [0,1)."))
		,
		createIndex();
	);
	// clang-format on
	REGISTER_CLASS_INDEX(ParallelBondMat, FrictMat);
};
REGISTER_SERIALIZABLE(ParallelBondMat);

class ParallelBondPhys : public RotStiffFrictPhys {
public:
	enum BondState { unbonded = 0, intact = 1, brokenTension = 2, brokenShear = 3 };
	bool isBonded() const { return bondState == intact; }
	void installBond(Real overlap, const Vector3r& direction);
	void setBondState(int state);
	Real bondEnergy() const;
	Real contactEnergy() const;
	void updateTotalStiffness();
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(ParallelBondPhys, RotStiffFrictPhys,
		"Physics of :yref:`ParallelBondMat` pairs: a linear contact and, once installed, a parallel bond. "
		"``kn``, ``ks`` and ``kr`` hold the total (contact + bond) stiffness so that "
		":yref:`GlobalStiffnessTimeStepper` sees the bond; ``normalForce`` and ``shearForce`` hold the total force "
		"on body 2 (contact + bond + dashpot), so YADE's stress and export tools work unchanged.",
		((Real, contactKn, 0, , "Contact normal stiffness $k_n$ [N/m]."))
		((Real, contactKs, 0, , "Contact shear stiffness $k_s$ [N/m]."))
		((Real, contactDamping, 0, , "Contact normal dashpot coefficient $c_n=2\\beta_n\\sqrt{m_{eff}k_n}$ [N·s/m]."))
		((Real, contactNormalForce, 0, , "Normal force of the contact spring [N], compression positive."))
		((Vector3r, contactShearForce, Vector3r::Zero(), , "Shear force of the contact spring on body 2 [N]."))
		((bool, isSlipping, false, , "Contact is sliding (Coulomb limit reached) this step."))
		((int, bondState, unbonded, , "0 never bonded, 1 intact bond, 2 broken in tension, 3 broken in shear."))
		((Real, bondRadius, 0, , "Bond radius $\\bar R$ [m]."))
		((Real, bondArea, 0, , "Bond area $A=2\\bar Rt$ [m²]."))
		((Real, bondInertia, 0, , "Bond moment of inertia $I=\\tfrac23\\bar R^3t$ [m⁴]."))
		((Real, bondKn, 0, , "Bond normal stiffness per area $\\bar k^n$ [N/m³]."))
		((Real, bondKs, 0, , "Bond shear stiffness per area $\\bar k^s$ [N/m³]."))
		((Real, bondDamping, 0, , "Bond normal dashpot coefficient $2\\bar\\beta_n\\sqrt{m_{eff}\\bar k^nA}$ [N·s/m]."))
		((Real, bondTensileStrength, 0, , "$\\bar\\sigma_c$ [Pa]."))
		((Real, bondCohesion, 0, , "$\\bar c$ [Pa]."))
		((Real, bondTanFriction, 0, , "$\\tan\\bar\\phi$ [-]."))
		((Real, bondRefOverlap, 0, , "Overlap when the bond was installed (bond is stress-free there) [m]."))
		((Vector3r, bondDirection0, Vector3r::Zero(), , "Unit vector from body 1 to body 2 when the bond was installed; the turn of the bond since is the rock's local rotation (see :yref:`Law2_ScGeom_SmoothJointPhys_SmoothJoint`)."))
		((Real, bondNormalForce, 0, , "Bond normal force $\\bar F_n$ [N], compression positive."))
		((Vector3r, bondShearForce, Vector3r::Zero(), , "Bond shear force $\\bar F_s$ on body 2 [N]."))
		((Real, bondMoment, 0, , "Bond moment $\\bar M$ about z on body 2 [N·m]."))
		((Real, bondSigmaMax, 0, , "Largest bond tensile stress $-\\bar F_n/A+|\\bar M|\\bar R/I$ [Pa] (last step)."))
		((Real, bondTauMax, 0, , "Bond shear stress $|\\bar F_s|/A$ [Pa] (last step)."))
		((Vector3r, normalBefore, Vector3r::Zero(), , "The contact normal the law saw at the last step: the shear forces turn with the contact from it (as :yref:`ScGeom` turns them)."))
		,
		createIndex();
		,
		.def("installBond", &ParallelBondPhys::installBond, (boost::python::arg("overlap"), boost::python::arg("direction")),
			"Install a stress-free bond at the current ``overlap`` (``geom.penetrationDepth``) [m] and centre-line "
			"``direction`` from body 1 to body 2 (``geom.normal``).")
		.def("bondEnergy", &ParallelBondPhys::bondEnergy, "Elastic energy stored in the bond [J].")
		.def("contactEnergy", &ParallelBondPhys::contactEnergy, "Elastic energy stored in the contact springs [J].")
	);
	// clang-format on
	REGISTER_CLASS_INDEX(ParallelBondPhys, RotStiffFrictPhys);
};
REGISTER_SERIALIZABLE(ParallelBondPhys);

class Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys : public IPhysFunctor {
public:
	void go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& interaction) override;
	FUNCTOR2D(ParallelBondMat, ParallelBondMat);
	DECLARE_LOGGER;

private:
	bool makeJoint(Interaction& interaction) const;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys, IPhysFunctor,
		"Creates :yref:`ParallelBondPhys` (unbonded) from two :yref:`ParallelBondMat`; see the material for the formulas. "
		"Where :yref:`joints<Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys.joints>` says the two discs straddle "
		"a joint, it creates that joint set's :yref:`SmoothJointPhys` instead: the one place that decides between "
		"rock and joint.",
		((shared_ptr<JointSystem>, joints, , , "The scene's joints (``toppling.build.joints`` sets it); none: all rock."))
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys);

} // namespace yade
