// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
Application
    interDemFoam

Description
    Two incompressible, isothermal, immiscible fluids (VoF, free surface)
    carrying the locally averaged equations of a fluid that shares its cells
    with DEM particles: the fluid volume fraction (porosity, "voidfraction")
    eps enters continuity, momentum and the phase-fraction transport

        d(eps)/dt + div(eps U) = 0                                  (seed eq. 8)
        d(eps alpha)/dt + div(eps U alpha) = 0        (seed eq. 10, with eps)
        d(eps rho U)/dt + div(eps rho U U) = - eps grad(p) + eps div(tau)
                          + eps rho g + eps F_s + f_pf              (seed eq. 9)

    Reference: Li et al. (2021), Front. Earth Sci. 9:673249, eq. 8-12.
    The particles and the exchange with LIGGGHTS live in libdemCoupling
    (class demCoupling::particleCloud); this file only orders the algorithm.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "CMULES.H"
#include "EulerDdtScheme.H"
#include "gaussConvectionScheme.H"
#include "upwind.H"
#include "subCycle.H"
#include "immiscibleIncompressibleTwoPhaseMixture.H"
#include "turbulentTransportModel.H"
#include "PhaseCompressibleTurbulenceModel.H"
#include "epsTurbulence.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "particleCloud.H"
#include "twoPhaseFluidView.H"
#include "demRestartFile.H"
#include "caseInputCheck.H"
#include "floatingPointStop.H"
#include "cfdStageTimes.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Two-phase VoF solver for the locally averaged equations of a fluid"
        " coupled to LIGGGHTS particles (CFD-DEM)."
    );

    demCoupling::demRestartFile::addOption();

    #include "postProcess.H"
    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"

    // controlDict before Time reads it (Time divides by writeInterval)
    demCoupling::caseInputCheck::controlDict(args);
    #include "selectDemStartTime.H"

    #include "createTime.H"
    demCoupling::floatingPointStop::install(runTime);
    #include "createMesh.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    #include "createFields.H"
    #include "createFvOptions.H"
    #include "initContinuityErrs.H"

    // The particles' drag damps the turbulence (RAS, LES with particles)
    particles.addTurbulenceDamping
    (
        fvOptions, rho, turbulence.solvedFields(mesh)
    );
    turbulence.validate();

    #include "CourantNo.H"
    #include "setInitialDeltaT.H"
    #include "initialDemDeltaT.H"

    // Wall time of the CFD's stages, printed with the timing split
    demCoupling::cfdStageTimes cfdTimes
    (
        {
            "phaseFraction", "continuityCorrection", "momentum", "pressure",
            "other"
        }
    );

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"
        #include "alphaCourantNo.H"
        const scalar maxDeltaTFact =
            min(maxCo/(CoNum + SMALL), maxAlphaCo/(alphaCoNum + SMALL));
        #include "setDemDeltaT.H"

        ++runTime;
        Info<< "Time = " << runTime.timeName() << nl << endl;

        // Coupling step: DEM advance, particle data, void fraction,
        // particle-fluid forces, fluid source terms (eps, Ksl, Us, fExplicit)
        particles.evolve();
        cfdTimes.restart();

        #include "readVoidFractionRate.H"

        while (pimple.loop())
        {
            #include "alphaControls.H"
            #include "alphaEqnSubCycle.H"
            mixture.correct();
            cfdTimes.mark("phaseFraction");

            #include "UEqn.H"
            cfdTimes.mark("momentum");

            while (pimple.correct())
            {
                #include "pEqn.H"
            }
            cfdTimes.mark("pressure");

            if (pimple.turbCorr())
            {
                turbulence.correct();
            }
        }

        #include "endDemStep.H"
        cfdTimes.mark("other");
        cfdTimes.endStep();
    }

    particles.printTimingSplit();
    cfdTimes.print(mesh);

    Info<< "End\n" << endl;

    return 0;
}

// ************************************************************************* //
