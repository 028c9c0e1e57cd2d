// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "couplingControls.H"
#include "demEngine.H"
#include "meshReach.H"
#include "inputCheck.H"
#include "couplingKeywords.H"
#include "Switch.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::demCoupling::couplingControls::outsidePolicy>
Foam::demCoupling::couplingControls::outsidePolicyNames
({
    { outsidePolicy::ignore, "ignore" },
    { outsidePolicy::remove, "delete" },
});

const Foam::Enum<Foam::demCoupling::couplingControls::demDragPolicy>
Foam::demCoupling::couplingControls::demDragPolicyNames
({
    { demDragPolicy::implicitDrag, "implicit" },
    { demDragPolicy::explicitForce, "explicit" },
});


namespace
{
    // The keywords of couplingProperties the controls read
    const Foam::demCoupling::couplingKeywords::declare keywords
    (
        {"outsideParticles", "demDrag"}
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::couplingControls::couplingControls
(
    const dictionary& dict,
    const Time& runTime
)
:
    dict_(dict),
    outside_(outsidePolicy::ignore),
    demDrag_(demDragPolicy::implicitDrag),
    demDragSet_(dict.found("demDrag")),
    adjustTimeStep_
    (
        runTime.controlDict().getOrDefault<Switch>("adjustTimeStep", false)
    )
{
    // Every keyword must be one some room of the library reads
    inputCheck::keywords(dict, couplingKeywords::allowed());

    outside_ = inputCheck::selectOrDefault
    (
        dict, "outsideParticles", outsidePolicyNames, outsidePolicy::ignore,
        "ignore (no fluid force on a particle outside the fluid mesh,"
        " counted) and delete (removed from the DEM)"
    );

    // How the DEM applies the drag (see docs/forces.md, "Quiet dense
    // beds"); without the keyword the DEM script decides (checkDem)
    demDrag_ = inputCheck::selectOrDefault
    (
        dict, "demDrag", demDragPolicyNames, demDragPolicy::implicitDrag,
        "implicit (the drag K (u - v) applied in every DEM step with the"
        " particle's velocity of that step; the default) and explicit (the"
        " whole force held over the coupling interval)"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demCoupling::couplingControls::resolveDemDrag
(
    const demEngine& engine
)
{
    if (!demDragSet_ && !engine.implicitDrag())
    {
        // A case written before demDrag existed: its script's
        // couple/cfd/force holds the whole force over the interval
        demDrag_ = demDragPolicy::explicitForce;
        Info<< "DEM drag: explicit (the DEM script " << engine.script()
            << " has couple/cfd/force, not couple/cfd/force/implicit, and "
            << dict_.name() << " sets no demDrag: the whole force is held"
            << " over the coupling interval, as before demDrag existed; set"
            << " demDrag explicit to say so, or use couple/cfd/force/implicit"
            << " for the drag in every DEM step)" << endl;
        return;
    }
    if (implicitDemDrag() && !engine.implicitDrag())
    {
        FatalIOErrorInFunction(dict_)
            << "demDrag implicit (set in " << dict_.name() << ") needs the"
            << " fix" << nl
            << "    fix cfd2 all couple/cfd/force/implicit" << nl
            << "in the DEM script " << engine.script() << " instead of"
            << " couple/cfd/force; or set demDrag explicit."
            << exit(FatalIOError);
    }
    Info<< "DEM drag: " << demDragPolicyNames[demDrag_] << endl;
}


void Foam::demCoupling::couplingControls::checkDem
(
    const demEngine& engine,
    const fvMesh& mesh
)
{
    resolveDemDrag(engine);

    // The DEM box must hold the whole fluid mesh: where it does not, a
    // particle leaves the DEM while still in the fluid
    const boundBox demBox(engine.box());
    const boundBox& meshBox = mesh.bounds();
    const scalar tol = reachTolerance*mag(meshBox.span());
    if
    (
        cmptMin(meshBox.min() - demBox.min()) < -tol
     || cmptMax(meshBox.max() - demBox.max()) > tol
    )
    {
        FatalIOErrorInFunction(dict_)
            << "The DEM box of " << engine.script() << ", "
            << demBox.min() << " to " << demBox.max() << ", does not"
            << " cover the fluid mesh, " << meshBox.min() << " to "
            << meshBox.max() << "." << nl
            << "    Enlarge the region of create_box in the DEM script"
            << " (it may be larger than the mesh, not smaller)."
            << exit(FatalIOError);
    }

    // A particle wider than the domain fits nowhere in it: its volume
    // cannot be spread over cells it does not fit in (the directions the
    // fluid solves for; a 2-D mesh's empty direction does not count)
    const scalar dMax = engine.largestDiameter();
    scalar domain = GREAT;
    for (direction k = 0; k < vector::nComponents; ++k)
    {
        if (mesh.geometricD()[k] > 0)
        {
            domain = min(domain, min(meshBox.span()[k], demBox.span()[k]));
        }
    }
    if (dMax > domain)
    {
        FatalIOErrorInFunction(dict_)
            << "The largest particle of the DEM script " << engine.script()
            << " has diameter " << dMax << " m, larger than the narrowest"
            << " extent of the fluid mesh and DEM box, " << domain << " m:"
            << " it does not fit in the domain." << nl
            << "    Particles must be smaller than the domain (and, for"
            << " the void-fraction models, at most about the size of a"
            << " cell; checkDemScene tells)." << exit(FatalIOError);
    }

    checkDemTimeStep(engine);
}


void Foam::demCoupling::couplingControls::checkDemTimeStep
(
    const demEngine& engine
)
{
    scalar dMin = 0, EMin = 0;
    const scalar tR = engine.rayleighTime(dMin, EMin);
    if (tR < 0)
    {
        Info<< "DEM: no youngsModulus/poissonsRatio per atom type: the time"
            << " step is not checked against the Rayleigh time" << endl;
        return;
    }
    if (tR >= GREAT)
    {
        return;   // no particles yet
    }

    const scalar dt = engine.timeStep();
    Info<< "DEM: time step " << dt << " s = " << 100*dt/tR << " % of the"
        << " Rayleigh time " << tR << " s" << endl;
    if (dt > 0.2*tR)
    {
        Info<< "Warning: the DEM time step " << dt << " s is " << 100*dt/tR
            << " % of the Rayleigh time " << tR << " s (smallest particle";
        if (dMin > 0)
        {
            Info<< " d = " << dMin << " m, E = " << EMin << " Pa";
        }
        Info<< "): contacts are under-resolved and may blow up." << nl
            << "    Use a timestep of at most 20 % of it (" << 0.2*tR
            << " s) in " << engine.script() << ", or a softer youngsModulus"
            << " (checkDemScene lists what the scene needs)." << endl;
    }
}


Foam::label Foam::demCoupling::couplingControls::demSteps
(
    const Time& runTime,
    const demEngine& engine
) const
{
    const scalar dtDem = engine.timeStep();
    const scalar ratio = runTime.deltaTValue()/dtDem;
    const label n = label(std::round(ratio));
    if (n < 1 || mag(ratio - n) > 1e-6*ratio)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "deltaT " << runTime.deltaTValue() << " s is not a whole"
            << " number of DEM steps (timestep " << dtDem << " s in "
            << engine.script() << "): ratio " << ratio << nl
            << "    Set deltaT to a whole multiple of the DEM timestep."
            << exit(FatalIOError);
    }
    if (!adjustTimeStep_ && n != engine.coupleEvery())
    {
        FatalIOErrorInFunction(dict_)
            << "The DEM script " << engine.script() << " has couple_every "
            << engine.coupleEvery() << ", but deltaT/timestep = "
            << runTime.deltaTValue() << "/" << dtDem << " = " << n
            << " DEM steps per coupling step." << nl
            << "    Set couple_every " << n << " in the fix couple/cfd,"
            << " or change deltaT in system/controlDict." << exit(FatalIOError);
    }
    return n;
}


Foam::scalar Foam::demCoupling::couplingControls::wholeDemSteps
(
    const Time& runTime,
    const scalar dtDem,
    const scalar dt,
    const scalar dtOld,
    const scalar dtLimit
)
{
    const label nOld = max(label(1), label(std::round(dtOld/dtDem)));

    label n = max(label(1), label(std::floor(dt/dtDem*(1 + 1e-9))));
    if (n <= nOld && dt > dtOld*(1 + 1e-9) && (nOld + 1)*dtDem <= dtLimit)
    {
        // Growth wanted but lost to rounding: one DEM step more
        n = nOld + 1;
    }

    // Land on the end time and on write times (writeControl runTime or
    // adjustableRunTime), in whole DEM steps
    const scalar t = runTime.value();
    auto capAt = [&](const scalar tTarget)
    {
        // nTo DEM steps to go: split them into equal coupling steps of at
        // most n (as Time::adjustDeltaT does), so the last one lands
        const label nTo = label(std::round((tTarget - t)/dtDem));
        if (nTo >= 1)
        {
            const label nSteps = (nTo + n - 1)/n;
            n = (nTo + nSteps - 1)/nSteps;
        }
    };
    capAt(runTime.endTime().value());

    const dictionary& control = runTime.controlDict();
    const word writeControl
    (
        control.getOrDefault<word>("writeControl", "timeStep")
    );
    if (writeControl == "runTime" || writeControl == "adjustableRunTime")
    {
        const scalar interval = control.get<scalar>("writeInterval");
        const scalar t0 = runTime.startTime().value();
        const scalar k = std::floor((t - t0)/interval + 1e-6) + 1;
        capAt(t0 + k*interval);
    }

    return n*dtDem;
}
