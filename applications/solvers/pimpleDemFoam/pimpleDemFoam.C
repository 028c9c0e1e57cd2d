// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
Application
    pimpleDemFoam

Description
    One incompressible, isothermal fluid (no free surface) carrying the
    locally averaged equations of a fluid that shares its cells with DEM
    particles: the fluid volume fraction (porosity, "voidfraction") eps
    enters continuity and momentum

        d(eps)/dt + div(eps U) = 0                                  (seed eq. 8)
        d(eps rho U)/dt + div(eps rho U U) = - eps grad(p) + eps div(tau)
                          + eps rho g + f_pf                        (seed eq. 9)

    interDemFoam's equations with one phase: for scenes without a free
    surface (packed and fluidized beds, particles in a pipe), where a VoF
    equation for water everywhere would model more than the scene needs.
    Same library (libdemCoupling), same couplingProperties and models;
    p_rgh = p - rho g.h is solved (Pa), rho from transportProperties.
    The like-for-like peer of OpenFOAM's DPMFoam.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "PhaseIncompressibleTurbulenceModel.H"
#include "epsTurbulence.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "particleCloud.H"
#include "singlePhaseFluidView.H"
#include "demRestartFile.H"
#include "caseInputCheck.H"
#include "floatingPointStop.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Single-phase incompressible solver for the locally averaged"
        " equations of a fluid coupled to LIGGGHTS particles (CFD-DEM)."
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

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"

        const scalar maxDeltaTFact = maxCo/(CoNum + SMALL);
        #include "setDemDeltaT.H"

        ++runTime;
        Info<< "Time = " << runTime.timeName() << nl << endl;

        // Coupling step: DEM advance, particle data, void fraction,
        // particle-fluid forces, fluid source terms (eps, Ksl, Us, fExplicit)
        particles.evolve();
        epsRho == voidfraction*rho;

        #include "readVoidFractionRate.H"

        while (pimple.loop())
        {
            #include "UEqn.H"

            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            if (pimple.turbCorr())
            {
                laminarTransport.correct();
                turbulence.correct();
            }
        }

        #include "endDemStep.H"
    }

    particles.printTimingSplit();

    Info<< "End\n" << endl;

    return 0;
}

// ************************************************************************* //
