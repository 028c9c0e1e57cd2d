// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "particleCloud.H"
#include "meshReach.H"
#include "demRestartFile.H"
#include "sceneMaps.H"
#include "inputCheck.H"
#include "couplingKeywords.H"
#include "turbulenceDragDamping.H"
#include "Switch.H"
#include "fvcFlux.H"
#include "zeroGradientFvPatchFields.H"
#include "fixedValueFvPatchFields.H"
#include "wallPolyPatch.H"
#include "fvcGrad.H"
#include "fvcDiv.H"
#include "surfaceFields.H"
#include "Time.H"
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <mpi.h>

const Foam::Enum
<
    Foam::demCoupling::particleCloud::voidFractionRateSource
>
Foam::demCoupling::particleCloud::voidFractionRateSourceNames
({
    { voidFractionRateSource::snapshot, "snapshot" },
    { voidFractionRateSource::flux, "flux" },
});


namespace
{
// The keywords of couplingProperties read here
const Foam::demCoupling::couplingKeywords::declare keywords({"dragDamping"});

// Open constant/couplingProperties if the case has one
Foam::autoPtr<Foam::IOdictionary> readCouplingDict(const Foam::fvMesh& mesh)
{
    using namespace Foam;

    IOobject io
    (
        "couplingProperties",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );

    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        return nullptr;
    }
    return autoPtr<IOdictionary>::New(io);
}

// A field the solver writes, created (value init) when 0/ lacks it
template<class Type>
Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh> couplingField
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const Foam::dimensioned<Type>& init,
    const Foam::IOobject::writeOption w = Foam::IOobject::AUTO_WRITE
)
{
    using namespace Foam;
    return GeometricField<Type, fvPatchField, volMesh>
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            w == IOobject::AUTO_WRITE
          ? IOobject::READ_IF_PRESENT
          : IOobject::NO_READ,
            w
        ),
        mesh,
        init,
        zeroGradientFvPatchField<Type>::typeName
    );
}

// Boundary types of the void fraction when 0/ has no voidfraction file:
// walls zeroGradient; open boundaries (inlets, outlets, atmosphere) fixed at
// 1, so the velocity given there is superficial (the flux through an open
// face is eps_f phi, and no particle volume crosses a boundary); constraint
// patches (cyclic, empty, processor, symmetry) their own type
Foam::wordList voidfractionPatchTypes(const Foam::fvMesh& mesh)
{
    using namespace Foam;
    const fvBoundaryMesh& patches = mesh.boundary();
    wordList types(patches.size());
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi].patch();
        if (isA<wallPolyPatch>(pp))
        {
            types[patchi] = zeroGradientFvPatchScalarField::typeName;
        }
        else if (polyPatch::constraintType(pp.type()))
        {
            types[patchi] = pp.type();
        }
        else
        {
            types[patchi] = fixedValueFvPatchScalarField::typeName;
        }
    }
    return types;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::particleCloud::particleCloud
(
    const fvMesh& mesh,
    const fluidView& fluid
)
:
    mesh_(mesh),
    fluid_(fluid),
    couplingDict_(readCouplingDict(mesh)),
    controls_(),
    engine_(),
    exchange_(),
    locator_(),
    voidFraction_(),
    forces_(),
    sampler_(),
    momentumCoupling_(),
    diagnostics_(),
    voidfraction_
    (
        IOobject
        (
            "voidfraction",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        voidfractionPatchTypes(mesh)
    ),
    Us_(couplingField(mesh, "Us", dimensionedVector(dimVelocity, Zero))),
    Ksl_
    (
        couplingField(mesh, "Ksl", dimensionedScalar("zero", dimDensity/dimTime, 0.0))
    ),
    fExplicit_
    (
        couplingField
        (
            mesh,
            "fExplicit",
            dimensionedVector(dimForce/dimVolume, Zero),
            IOobject::NO_WRITE
        )
    ),
    solidFlux_
    (
        couplingField
        (
            mesh,
            "solidFlux",
            dimensionedVector(dimVelocity, Zero),
            IOobject::NO_WRITE
        )
    ),
    owned_(),
    particles_(),
    states_(),
    fluidForce_(),
    K_(),
    reactingForce_(),
    Uf_(),
    demK_(),
    demForce_(),
    forcesSent_(false),
    demSteps_(0),
    lastDemCount_(0),
    deletedNow_(0),
    deletedTotal_(0),
    cellsPerStep_(0)
{
    // Keep the previous time level of eps for d(eps)/dt
    voidfraction_.oldTime();

#ifdef __GLIBC__
    // Every step allocates and frees per-cell fields (gradients, fluxes,
    // tensors) and per-particle arrays of megabytes. glibc serves blocks
    // that large with fresh mmaps (and trims the heap on free), so each one
    // comes back as zeroed pages, one page fault per 4 kB: that was half
    // the coupling time of a 1e5-particle run, and half of interFoam's own
    // step on the flagship's mesh on a machine where page faults are
    // expensive (docs/benchmarks.md, Against its floors). Keep them in the
    // heap instead, with or without particles.
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif

    if (!active())
    {
        Info<< "No constant/couplingProperties: no particles, the fluid"
            << " volume fraction stays 1 (the solver without particles)."
            << nl << endl;
        return;
    }

    const dictionary& dict = couplingDict_();


    Info<< "Coupling to the DEM (" << couplingDict_().objectPath() << ")"
        << endl;

    controls_.reset(new couplingControls(dict, mesh.time()));

    // Models first (cheap, and their input errors come before the DEM's)
    voidFraction_ = voidFractionModel::New(dict, mesh);
    forces_ = forceModel::NewList(dict);
    sampler_.reset(new fluidSampler(dict, mesh, forces_));
    momentumCoupling_ = momentumCouplingModel::New(dict, mesh);
    exchange_ = particleExchange::New(dict, mesh);
    locator_.reset(new particleLocator(mesh));

    engine_.reset(new demEngine(dict, mesh.time()));
    controls_->checkDem(engine_(), mesh);

    // The particles' volume from the start, so that time 0 sees it
    updateParticles();
    voidfraction_.oldTime() = voidfraction_;
    checkParticleSizes();
    lastDemCount_ = exchange_->nTotal();

    // The coupling split counts the coupling steps only
    diagnostics_.startCouplingSplit(exchange_->seconds());
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::demCoupling::particleCloud::advanceDem()
{
    // In parallel the DEM phase ends when its slowest rank is done: the
    // wait for it is DEM time (LIGGGHTS's load balance), not time the
    // exchange that follows spends in its collectives
    const scalar t0 = diagnostics_.now();
    engine_->advance(demSteps_);
    if (Pstream::parRun())
    {
        MPI_Barrier(solverComm());
    }
    diagnostics_.addDem(diagnostics_.now() - t0);
}


void Foam::demCoupling::particleCloud::updateParticles()
{
    engine_->ownedParticles(owned_);

    // Each particle checked once, by the rank that owns it
    forAll(owned_.position, i)
    {
        if
        (
            !std::isfinite(magSqr(owned_.position[i]))
         || !std::isfinite(magSqr(owned_.velocity[i]))
        )
        {
            FatalErrorInFunction
                << "DEM particle " << owned_.tag[i] << " has a non-finite"
                << " position " << owned_.position[i] << " or velocity "
                << owned_.velocity[i] << " at t = "
                << mesh_.time().timeName() << " s: the DEM blew up." << nl
                << "    Check the DEM time step against the Rayleigh time"
                << " printed at the start, and the overlaps of the initial"
                << " packing. Results up to the last write time are kept."
                << exit(FatalError);
        }
    }

    exchange_->distribute
    (
        owned_,
        voidFraction_->reachFactor(),
        voidFraction_->reachesCellCentres(),
        particles_
    );

    const scalar t0 = diagnostics_.now();
    const scalar x0 = exchange_->seconds();
    locator_->locate(particles_, exchange_());
    const scalar t1 = diagnostics_.now();
    const scalar x1 = exchange_->seconds();
    diagnostics_.addLocate((t1 - t0) - (x1 - x0));

    voidFraction_->update(particles_, exchange_(), voidfraction_);
    diagnostics_.addVoidFraction
    (
        (diagnostics_.now() - t1) - (exchange_->seconds() - x1)
    );
}


void Foam::demCoupling::particleCloud::deleteOutsideParticles()
{
    deletedNow_ = 0;
    if (!controls_->deleteOutside() || !locator_->lost())
    {
        return;
    }
    // Each lost particle is counted by one rank: all ranks' lists
    List<labelList> perRank(Pstream::nProcs());
    perRank[Pstream::myProcNo()] = locator_->lostTags();
    Pstream::gatherList(perRank);
    Pstream::scatterList(perRank);
    DynamicList<label> tags;
    for (const labelList& l : perRank)
    {
        tags.append(l);
    }
    engine_->deleteParticles(tags);
    deletedNow_ = tags.size();
    deletedTotal_ += deletedNow_;
    // not a loss LIGGGHTS made: keep it out of the "left the DEM" count
    lastDemCount_ -= deletedNow_;
    updateParticles();
}


Foam::scalar Foam::demCoupling::particleCloud::maxCellsPerStep() const
{
    // Above one cell per coupling step the fluid a particle sees jumps
    // (and so do its forces): the largest (|u| dt)^3/V_cell, one cube root
    // (a cube root per particle was a tenth of the coupling time)
    const scalarField& V = mesh_.V();
    const scalar dt = mesh_.time().deltaTValue();
    scalar maxCube = 0;
    forAll(particles_.cell, i)
    {
        const label c = particles_.cell[i];
        if (c >= 0 && particles_.hostProc[i] == Pstream::myProcNo())
        {
            maxCube = max
            (
                maxCube,
                pow3(mag(particles_.velocity[i])*dt)/V[c]
            );
        }
    }
    return cbrt(returnReduce(maxCube, maxOp<scalar>()));
}


void Foam::demCoupling::particleCloud::checkParticleSizes() const
{
    // The smallest dx/d over the particles in the mesh (dx = cbrt(V) of
    // the host cell), each counted by its host rank
    const scalarField& V = mesh_.V();
    scalar dxOverD = GREAT;
    forAll(particles_.cell, i)
    {
        const label c = particles_.cell[i];
        if
        (
            c >= 0 && particles_.hostProc[i] == Pstream::myProcNo()
         && particles_.diameter[i] > 0
        )
        {
            dxOverD = min(dxOverD, cbrt(V[c])/particles_.diameter[i]);
        }
    }
    reduce(dxOverD, minOp<scalar>());
    const fileName dir(sceneMaps::defaultDir());
    if (dxOverD >= GREAT || !sceneMaps::available(dir))
    {
        return;   // no particle in the mesh yet, or no maps to ask
    }
    const sceneMaps maps(dir);
    const word& model = voidFraction_->type();
    scalar at = -1;
    const int stable = maps.bounded(model, dxOverD, at);
    if (stable == 0)
    {
        Info<< "Warning: the largest particle against its cell has dx/d = "
            << dxOverD << " (d " << 1/dxOverD << " of the cell size): the"
            << " void-fraction model " << model << " went unstable at dx/d"
            << " = " << at << " in the project's stability map ("
            << dir/"stabilityMap.dat" << "). Use coarser cells or another"
            << " model (checkDemScene tells what the scene needs)." << endl;
    }
    else if (stable < 0 && at > 0)
    {
        Info<< "Warning: the largest particle against its cell has dx/d = "
            << dxOverD << " (d " << 1/dxOverD << " of the cell size), below"
            << " the smallest cell size the void-fraction model " << model
            << " was measured at (dx/d = " << at << ", " << dir << "): its"
            << " accuracy and stability there are not known (checkDemScene"
            << " tells what the scene needs)." << endl;
    }
}


void Foam::demCoupling::particleCloud::sampleFluid()
{
    states_ = sampler_->sample
    (
        voidFraction_(), fluid_, voidfraction_, particles_, exchange_()
    );
}


void Foam::demCoupling::particleCloud::computeForces()
{
    const label n = particles_.size();
    const voidFractionModel& vf = voidFraction_();

    fluidForce_.setSize(n);
    K_.setSize(n);
    reactingForce_.setSize(n);
    Uf_.setSize(n);
    demK_.setSize(n);
    demForce_.setSize(n);
    fluidForce_ = Zero;
    K_ = 0;
    reactingForce_ = Zero;
    Uf_ = Zero;
    demK_ = 0;
    demForce_ = Zero;

    // A fluid velocity taken at the particle's centre, or with turbulent
    // fluctuations, while the fluid reacts at its cells' velocities: the
    // difference K (u - u_average) goes to the fluid explicitly, so that
    // it loses what the particle gains (fluidSampler.H)
    const bool reactionAtAverage =
        sampler_->velocityDiffersFromAverage()
     && momentumCoupling_->reactsAtCellVelocity();

    // Every processor that holds cells of a particle computes the same
    // force from the same (combined) fluid state
    forAll(states_, i)
    {
        if (vf.cells(i).empty())
        {
            continue;
        }
        const particleFluidState& s = states_[i];
        Uf_[i] = s.Uf;

        for (const forceModel& model : forces_)
        {
            const particleForce f(model.force(s));
            fluidForce_[i] += f.total(s);
            demK_[i] += f.K;
            if (model.reactsOnFluid())
            {
                K_[i] += f.K;
                reactingForce_[i] += f.explicitForce;
            }
        }

        demForce_[i] = fluidForce_[i] - demK_[i]*(s.Uf - s.Up);
        if (reactionAtAverage)
        {
            reactingForce_[i] += K_[i]*(s.Uf - s.UfAverage);
        }

        if (!std::isfinite(magSqr(fluidForce_[i])) || !std::isfinite(K_[i]))
        {
            FatalErrorInFunction
                << "Non-finite fluid force " << fluidForce_[i]
                << " on DEM particle " << particles_.tag[i]
                << " at " << particles_.position[i]
                << " (time " << mesh_.time().timeName() << "): fluid"
                << " velocity " << s.Uf << ", eps " << s.eps
                << ", rho " << s.rhoF << ", mu " << s.muF
                << ", grad(p) " << s.gradP << nl
                << "    Results up to the last write time are kept."
                << exit(FatalError);
        }
    }
}


void Foam::demCoupling::particleCloud::assembleSources()
{
    // The solid volume flux of the interval just run
    {
        List<vector> Vv(particles_.size());
        forAll(Vv, i)
        {
            Vv[i] = particles_.volume(i)*particles_.meanVelocity[i];
        }
        solidFlux_.primitiveFieldRef() = voidFraction_->spread(Vv);
        solidFlux_.correctBoundaryConditions();
    }

    // The fluid receives the reaction of the force the particles got. With
    // demDrag implicit that is the drag the DEM applied in the interval
    // just run, K (u - v) at every step with the DEM's K and u of it: its
    // mean is K (u - mean v), mean v the displacement over the interval
    if (controls_->implicitDemDrag())
    {
        momentumCoupling_->assemble
        (
            particles_, voidFraction_(), particles_.demK, particles_.demUf,
            particles_.meanVelocity, reactingForce_, Ksl_, Us_, fExplicit_
        );
    }
    else
    {
        momentumCoupling_->assemble
        (
            particles_, voidFraction_(), K_, Uf_, particles_.velocity,
            reactingForce_, Ksl_, Us_, fExplicit_
        );
    }
}

void Foam::demCoupling::particleCloud::sendForces()
{
    // Summed over the ranks that hold a particle: the host's only
    List<vector> hostForce(controls_->implicitDemDrag() ? demForce_ : fluidForce_);
    scalarList hostKUf(controls_->implicitDemDrag() ? 4*hostForce.size() : 0, Zero);
    forAll(hostForce, i)
    {
        if (particles_.hostProc[i] != Pstream::myProcNo())
        {
            hostForce[i] = Zero;
        }
        else if (controls_->implicitDemDrag())
        {
            hostKUf[4*i] = demK_[i];
            for (direction k = 0; k < 3; ++k)
            {
                hostKUf[4*i + 1 + k] = Uf_[i][k];
            }
        }
    }
    if (controls_->implicitDemDrag())
    {
        const scalarList KUf(exchange_->toOwners(hostKUf, 4));
        scalarList K(KUf.size()/4);
        List<vector> Uf(K.size());
        forAll(K, i)
        {
            K[i] = KUf[4*i];
            Uf[i] = vector(KUf[4*i + 1], KUf[4*i + 2], KUf[4*i + 3]);
        }
        engine_->setForces(exchange_->toOwners(hostForce), K, Uf);
    }
    else
    {
        engine_->setForces
        (
            exchange_->toOwners(hostForce), scalarList(), List<vector>()
        );
    }
    forcesSent_ = true;

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::demCoupling::particleCloud::wholeDemSteps
(
    const scalar dt,
    const scalar dtOld,
    const scalar dtLimit
) const
{
    if (!active())
    {
        return dt;
    }
    return couplingControls::wholeDemSteps
    (
        mesh_.time(), engine_->timeStep(), dt, dtOld, dtLimit
    );
}


void Foam::demCoupling::particleCloud::evolve()
{
    if (!active())
    {
        return;
    }

    // DEM steps in this coupling step: a whole number
    demSteps_ = controls_->demSteps(mesh_.time(), engine_());

    // 0. Before the first DEM advance of a fresh start: the fluid forces of
    //    the initial state (else the first interval would run without
    //    them: a free fall of one coupling interval). A restarted DEM
    //    holds, from its restart file, the forces it had at that time.
    if (!forcesSent_ && !engine_->restarted())
    {
        sampleFluid();
        computeForces();
        assembleSources();
        sendForces();
    }

    advanceDem();                           // 1. DEM advance
    const scalar t1 = diagnostics_.now();

    updateParticles();                      // 2-4. particles in, locate,
                                            //      void fraction
    deleteOutsideParticles();               // (outsideParticles delete)
    cellsPerStep_ = maxCellsPerStep();

    const scalar tf = diagnostics_.now();
    const scalar xf = exchange_->seconds();
    sampleFluid();                          // 5. fluid at the particles
    computeForces();                        // 6. forces
    assembleSources();                      // 7. fluid sources
    diagnostics_.addForces
    (
        (diagnostics_.now() - tf) - (exchange_->seconds() - xf)
    );

    sendForces();                           // 8. forces out

    diagnostics_.addCoupling(diagnostics_.now() - t1);
    diagnostics_.addParticleSteps(exchange_->nTotal());
}


void Foam::demCoupling::particleCloud::report()
{
    if (!active())
    {
        diagnostics_.report(mesh_.time(), nullptr);
        return;
    }

    couplingStepReport step;
    for (const label c : particles_.cell)
    {
        if (c >= 0) ++step.hosted;
    }
    reduce(step.hosted, sumOp<label>());
    step.nDem = exchange_->nTotal();
    step.demSteps = demSteps_;
    step.minVoidFraction = gMin(voidfraction_);
    step.lostByDem = max(lastDemCount_ - step.nDem, label(0));
    lastDemCount_ = step.nDem;
    step.deleted = deletedNow_;
    step.deletedTotal = deletedTotal_;
    step.outside = locator_->lost();
    step.floorHits = voidFraction_->floorHits();
    step.totalFloorHits = voidFraction_->totalFloorHits();
    step.floor = voidFraction_->minVoidFraction();
    step.spilledCells = voidFraction_->spilledCells();
    step.totalSpilledCells = voidFraction_->totalSpilledCells();
    step.cellsPerStep = cellsPerStep_;

    diagnostics_.report(mesh_.time(), &step);
}


void Foam::demCoupling::particleCloud::writeParticles() const
{
    if (active())
    {
        demRestartFile::guardWrite
        (
            mesh_.time(),
            [this]()
            {
                couplingDiagnostics::writeParticles
                (
                    mesh_, particles_, fluidForce_
                );
            }
        );
    }
}


Foam::tmp<Foam::volScalarField>
Foam::demCoupling::particleCloud::voidFractionRateFromFlux() const
{
    surfaceScalarField phiSolid(fvc::flux(solidFlux_));
    for (fvsPatchScalarField& pf : phiSolid.boundaryFieldRef())
    {
        if (!pf.coupled())
        {
            pf = 0;
        }
    }
    return fvc::div(phiSolid);
}


void Foam::demCoupling::particleCloud::addTurbulenceDamping
(
    fv::optionList& fvOptions,
    const volScalarField& rho,
    const wordList& turbulenceFields
) const
{
    if (!active() || turbulenceFields.empty())
    {
        return;
    }
    if (!couplingDict_().getOrDefault<Switch>("dragDamping", true))
    {
        Info<< "Turbulence not damped by the particles (dragDamping no in "
            << couplingDict_().name() << ")" << endl;
        return;
    }
    fvOptions.append
    (
        new turbulenceDragDamping(mesh_, Ksl_, rho, turbulenceFields)
    );
}


bool Foam::demCoupling::particleCloud::rateFromFlux
(
    const dictionary& pimpleDict
) const
{
    const voidFractionRateSource source = inputCheck::selectOrDefault
    (
        pimpleDict, "voidFractionRate", voidFractionRateSourceNames,
        voidFractionRateSource::flux,
        "snapshot (eps difference of two steps) and flux (div of the solid"
        " volume flux)"
    );
    return source == voidFractionRateSource::flux && active();
}


void Foam::demCoupling::particleCloud::writeDemRestart()
{
    if (active())
    {
        engine_->writeRestart(mesh_.time());
    }
}


void Foam::demCoupling::particleCloud::checkFinite(Time& runTime) const
{
    couplingDiagnostics::checkFinite
    (
        runTime, fluid_.U(), fluid_.solvedPressure(), voidfraction_
    );
}


void Foam::demCoupling::particleCloud::printTimingSplit() const
{
    diagnostics_.printTimingSplit
    (
        active(),
        active() ? exchange_->seconds() : 0,
        active() ? exchange_->nTotal() : 0,
        particles_.size()
    );
    if (active())
    {
        exchange_->printTraffic();
    }
}


// ************************************************************************* //
