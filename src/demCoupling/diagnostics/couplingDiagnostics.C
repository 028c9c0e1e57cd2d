// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "couplingDiagnostics.H"
#include "passiveParticleCloud.H"
#include "IOField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::couplingDiagnostics::couplingDiagnostics()
:
    clock_(),
    startTime_(clock_.elapsedTime()),
    lastProgress_(startTime_),
    demTime_(0),
    couplingTime_(0),
    locateTime_(0),
    voidFractionTime_(0),
    forcesTime_(0),
    particleSteps_(0),
    exchangeStart_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demCoupling::couplingDiagnostics::startCouplingSplit
(
    const scalar exchange
)
{
    locateTime_ = 0;
    voidFractionTime_ = 0;
    exchangeStart_ = exchange;
}


void Foam::demCoupling::couplingDiagnostics::report
(
    const Time& runTime,
    const couplingStepReport* step
)
{
    if (step)
    {
        const couplingStepReport& s = *step;
        Info<< "Particles: " << s.nDem << " in the DEM, "
            << s.hosted << " in the mesh, " << s.demSteps << " DEM steps,"
            << " min(voidfraction) " << s.minVoidFraction << endl;

        if (s.lostByDem > 0)
        {
            Info<< "Warning: " << s.lostByDem
                << " particle(s) left the DEM domain at t = "
                << runTime.timeName() << " s (LIGGGHTS dropped them); "
                << s.nDem << " remain" << endl;
        }

        if (s.deleted)
        {
            Info<< "Deleted " << s.deleted << " particle(s) outside the"
                << " fluid mesh at t = " << runTime.timeName() << " s ("
                << s.deletedTotal << " since the start; outsideParticles"
                << " delete)" << endl;
        }
        else if (s.outside)
        {
            Info<< "Warning: " << s.outside << " particle(s) outside"
                << " the fluid mesh at t = " << runTime.timeName()
                << " s: no fluid force on them (outsideParticles ignore;"
                << " 'delete' removes them from the DEM)" << endl;
        }
        if (s.spilledCells)
        {
            Info<< "Voidfraction spill: " << s.spilledCells << " cell(s)"
                << " held more solid than 1 - " << s.floor << " and moved"
                << " the rest to their neighbours at t = "
                << runTime.timeName() << " s (" << s.totalSpilledCells
                << " since the start)" << endl;
        }
        if (s.floorHits)
        {
            Info<< "Warning: voidfraction floor " << s.floor
                << " hit in " << s.floorHits << " cell(s) at"
                << " t = " << runTime.timeName() << " s ("
                << s.totalFloorHits << " since the start):"
                << " more particle volume than these cells hold. Use a"
                << " void-fraction model that spreads wider (virtualSphere,"
                << " diffusion) or larger cells; lowering minVoidFraction"
                << " only hides it. checkDemScene lists what the scene"
                << " needs." << endl;
        }
        if (s.cellsPerStep > 1)
        {
            Info<< "Warning: a particle crossed " << s.cellsPerStep
                << " cells in one coupling step at t = " << runTime.timeName()
                << " s: the fluid it sees jumps between steps. Reduce deltaT"
                << " (fewer DEM steps per coupling step); checkDemScene"
                << " lists what the scene needs." << endl;
        }
    }

    // Progress of long runs: every 30 s of wall time and at the end
    const scalar now = clock_.elapsedTime();
    const scalar tNow = runTime.value();
    const scalar tEnd = runTime.endTime().value();
    const scalar tStart = runTime.startTime().value();
    const bool last = tNow >= tEnd - 0.5*runTime.deltaTValue();
    if (now - lastProgress_ >= 30 || last)
    {
        lastProgress_ = now;
        const scalar wall = now - startTime_;
        const scalar done = (tNow - tStart)/max(tEnd - tStart, VSMALL);
        const scalar eta = done > 0 ? wall*(1 - done)/done : 0;
        Info<< "Progress: t = " << tNow << " s of " << tEnd << " s ("
            << label(100*done) << " %), wall " << label(wall) << " s, ETA "
            << label(eta) << " s" << endl;
    }
}


void Foam::demCoupling::couplingDiagnostics::printTimingSplit
(
    const bool coupled,
    const scalar exchangeSeconds,
    const label nParticles,
    const label held
) const
{
    const scalar total = clock_.elapsedTime() - startTime_;
    const scalar cfd = max(total - demTime_ - couplingTime_, scalar(0));

    Info<< "Timing split: DEM " << demTime_ << " s, CFD " << cfd
        << " s, coupling " << couplingTime_ << " s" << endl;

    if (coupled)
    {
        Info<< "Coupling split: exchange "
            << exchangeSeconds - exchangeStart_
            << " s, locate " << locateTime_ << " s, void fraction "
            << voidFractionTime_ << " s, forces " << forcesTime_ << " s ("
            << particleSteps_ << " particle steps, "
            << 1e6*couplingTime_/max(particleSteps_, scalar(1))
            << " us per particle per coupling step)" << endl;
        if (Pstream::parRun())
        {
            Info<< "Particles held per rank at the end: min "
                << returnReduce(held, minOp<label>()) << ", max "
                << returnReduce(held, maxOp<label>()) << " (of "
                << nParticles << " in the DEM)" << endl;
        }
    }
}


void Foam::demCoupling::couplingDiagnostics::writeParticles
(
    const fvMesh& mesh,
    const particleData& particles,
    const List<vector>& fluidForce
)
{
    IDLList<passiveParticle> list;
    DynamicList<scalar> d;
    DynamicList<vector> Up, F, omega;
    DynamicList<label> id, type;
    forAll(particles.cell, i)
    {
        if (particles.cell[i] < 0)
        {
            continue;
        }
        list.append
        (
            new passiveParticle(mesh, particles.position[i], particles.cell[i])
        );
        d.append(particles.diameter[i]);
        Up.append(particles.velocity[i]);
        F.append(i < fluidForce.size() ? fluidForce[i] : Zero);
        omega.append(particles.omega[i]);
        id.append(particles.tag[i]);
        type.append(particles.type[i]);
    }

    passiveParticleCloud cloud(mesh, "demParticles", list);
    cloud.write();

    if (cloud.size())
    {
        IOField<scalar>(cloud.fieldIOobject("d", IOobject::NO_READ), d).write();
        IOField<vector>(cloud.fieldIOobject("U", IOobject::NO_READ), Up).write();
        IOField<vector>(cloud.fieldIOobject("F", IOobject::NO_READ), F).write();
        IOField<vector>
        (
            cloud.fieldIOobject("omega", IOobject::NO_READ), omega
        ).write();
        IOField<label>(cloud.fieldIOobject("id", IOobject::NO_READ), id).write();
        IOField<label>
        (
            cloud.fieldIOobject("type", IOobject::NO_READ), type
        ).write();
    }
}


void Foam::demCoupling::couplingDiagnostics::checkFinite
(
    Time& runTime,
    const volVectorField& U,
    const volScalarField& p,
    const volScalarField& voidfraction
)
{
    // One reduction for the three fields; the names of the bad ones
    scalarList sums
    ({
        sumMag(U.primitiveField()),
        sumMag(p.primitiveField()),
        sumMag(voidfraction.primitiveField())
    });
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    const wordList names({U.name(), p.name(), voidfraction.name()});
    wordList bad;
    forAll(sums, i)
    {
        if (!std::isfinite(sums[i]))
        {
            bad.append(names[i]);
        }
    }
    if (bad.size())
    {
        runTime.writeNow();
        FatalErrorInFunction
            << "NaN or Inf in the fluid field(s) " << flatOutput(bad)
            << " at t = " << runTime.timeName() << " s." << nl
            << "    The fields of this time are written for inspection;"
            << " results of earlier write times are kept." << nl
            << "    Reduce deltaT (maxCo), check the boundary conditions, and"
            << " look for voidfraction floor hits above." << exit(FatalError);
    }
}
