// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "particleCloud.H"
#include "fvcFlux.H"
#include "immiscibleIncompressibleTwoPhaseMixture.H"
#include "zeroGradientFvPatchFields.H"
#include "fixedValueFvPatchFields.H"
#include "wallPolyPatch.H"
#include "fvcGrad.H"
#include "fvcReconstruct.H"
#include "fvcCurl.H"
#include "fvcDiv.H"
#include "fvcLaplacian.H"
#include "surfaceFields.H"
#include "Time.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <mpi.h>

namespace
{
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

// Levenshtein distance, for "did you mean"
Foam::label editDistance(const std::string& a, const std::string& b)
{
    std::vector<Foam::label> prev(b.size() + 1), cur(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
    {
        cur[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
        {
            const Foam::label sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
            cur[j] = std::min(std::min(prev[j] + 1, cur[j - 1] + 1), sub);
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

// Every keyword of couplingProperties must be one this code reads: a typo
// ("minVoidfraction") would otherwise fall back to a default or be
// ignored without a word
void checkKeywords(const Foam::dictionary& dict)
{
    using namespace Foam;
    using namespace Foam::demCoupling;

    wordList known
    ({
        "demScript", "demRestartScript", "voidFraction", "minVoidFraction",
        "forces", "momentumCoupling", "outsideParticles", "exchange",
        "demDrag"
    });
    for (const word& m : voidFractionModel::dictionaryConstructorTablePtr_->sortedToc())
    {
        known.append(m + "Coeffs");
    }
    for (const word& m : forceModel::dictionaryConstructorTablePtr_->sortedToc())
    {
        known.append(m + "Coeffs");
    }

    for (const word& key : dict.toc())
    {
        if (key == "FoamFile" || known.found(key))
        {
            continue;
        }
        word best;
        label bestDistance = labelMax;
        for (const word& k : known)
        {
            const label d = editDistance(key, k);
            if (d < bestDistance)
            {
                bestDistance = d;
                best = k;
            }
        }
        FatalIOErrorInFunction(dict)
            << "Unknown keyword '" << key << "' in " << dict.name() << nl;
        if (bestDistance <= max(label(2), label(key.size()/3)))
        {
            FatalIOError << "    Did you mean '" << best << "'?" << nl;
        }
        FatalIOError
            << "    Allowed: " << flatOutput(known) << exit(FatalIOError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::particleCloud::particleCloud
(
    const fvMesh& mesh,
    const volVectorField& U,
    const volScalarField& rho,
    const immiscibleIncompressibleTwoPhaseMixture& mixture
)
:
    mesh_(mesh),
    U_(U),
    rho_(rho),
    mixture_(mixture),
    couplingDict_(readCouplingDict(mesh)),
    engine_(),
    exchange_(),
    locator_(),
    voidFraction_(),
    forces_(),
    momentumCoupling_(),
    adjustTimeStep_
    (
        mesh.time().controlDict().getOrDefault<Switch>("adjustTimeStep", false)
    ),
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
    fluidForce_(),
    K_(),
    reactingForce_(),
    Uf_(),
    demSteps_(0),
    lastDemCount_(0),
    outsidePolicy_("ignore"),

    deletedNow_(0),
    deletedTotal_(0),
    cellsPerStep_(0),
    clock_(),
    demTime_(0),
    couplingTime_(0),
    locateTime_(0),
    voidFractionTime_(0),
    forcesTime_(0),
    particleSteps_(0),
    exchangeStart_(0),
    startTime_(clock_.elapsedTime()),
    lastProgress_(startTime_)
{
    // Keep the previous time level of eps for d(eps)/dt
    voidfraction_.oldTime();

    if (!active())
    {
        Info<< "No constant/couplingProperties: no particles, the fluid"
            << " volume fraction stays 1 (plain two-phase VoF)." << nl
            << endl;
        return;
    }

    const dictionary& dict = couplingDict_();

#ifdef __GLIBC__
    // Every coupling step allocates and frees per-particle and per-cell
    // arrays of megabytes. glibc serves blocks that large with fresh mmaps
    // (and trims the heap on free), so each one comes back as zeroed pages,
    // one page fault per 4 kB: that was half the coupling time of a 1e5-
    // particle run. Keep them in the heap instead.
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif

    Info<< "Coupling to the DEM (" << couplingDict_().objectPath() << ")"
        << endl;

    checkKeywords(dict);

    outsidePolicy_ = dict.getOrDefault<word>("outsideParticles", "ignore");
    if (outsidePolicy_ != "ignore" && outsidePolicy_ != "delete")
    {
        FatalIOErrorInFunction(dict)
            << "outsideParticles '" << outsidePolicy_ << "' in "
            << dict.name() << ": allowed are ignore (no fluid force on a"
            << " particle outside the fluid mesh, counted) and delete"
            << " (removed from the DEM)" << exit(FatalIOError);
    }

    // Models first (cheap, and their input errors come before the DEM's)
    voidFraction_ = voidFractionModel::New(dict, mesh);
    forces_ = forceModel::NewList(dict);
    momentumCoupling_ = momentumCouplingModel::New(dict, mesh);
    exchange_ = particleExchange::New(dict, mesh);
    locator_.reset(new particleLocator(mesh));

    engine_.reset(new demEngine(dict, mesh.time()));

    // How the DEM applies the drag (see docs/forces.md, "Quiet dense beds")
    const word demDrag(dict.getOrDefault<word>("demDrag", "implicit"));
    if (demDrag != "implicit" && demDrag != "explicit")
    {
        FatalIOErrorInFunction(dict)
            << "demDrag '" << demDrag << "' in " << dict.name() << ": allowed"
            << " are implicit (the drag K (u - v) applied in every DEM step"
            << " with the particle's velocity of that step; the default) and"
            << " explicit (the whole force held over the coupling interval)"
            << exit(FatalIOError);
    }
    implicitDemDrag_ = demDrag == "implicit";
    if (implicitDemDrag_ && !engine_->implicitDrag())
    {
        FatalIOErrorInFunction(dict)
            << "demDrag implicit (" << (dict.found("demDrag") ? "set" : "the"
            " default") << " in " << dict.name() << ") needs the fix" << nl
            << "    fix cfd2 all couple/cfd/force/implicit" << nl
            << "in the DEM script " << engine_->script() << " instead of"
            << " couple/cfd/force; or set demDrag explicit."
            << exit(FatalIOError);
    }
    Info<< "DEM drag: " << demDrag << endl;

    // The DEM box must hold the whole fluid mesh: where it does not, a
    // particle leaves the DEM while still in the fluid
    {
        const boundBox demBox(engine_->box());
        const boundBox& meshBox = mesh.bounds();
        const scalar tol = 1e-6*mag(meshBox.span());
        if
        (
            cmptMin(meshBox.min() - demBox.min()) < -tol
         || cmptMax(meshBox.max() - demBox.max()) > tol
        )
        {
            FatalIOErrorInFunction(dict)
                << "The DEM box of " << engine_->script() << ", "
                << demBox.min() << " to " << demBox.max() << ", does not"
                << " cover the fluid mesh, " << meshBox.min() << " to "
                << meshBox.max() << "." << nl
                << "    Enlarge the region of create_box in the DEM script"
                << " (it may be larger than the mesh, not smaller)."
                << exit(FatalIOError);
        }
    }
    engine_->checkTimeStep();

    // The particles' volume from the start, so that time 0 sees it
    updateParticles();
    voidfraction_.oldTime() = voidfraction_;
    lastDemCount_ = exchange_->nTotal();

    // The coupling split counts the coupling steps only
    locateTime_ = 0;
    voidFractionTime_ = 0;
    exchangeStart_ = exchange_->seconds();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

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

    scalar t0 = clock_.elapsedTime();
    scalar x0 = exchange_->seconds();
    locator_->locate(particles_);
    scalar t1 = clock_.elapsedTime();
    scalar x1 = exchange_->seconds();
    locateTime_ += (t1 - t0) - (x1 - x0);

    voidFraction_->update(particles_, voidfraction_);
    voidFractionTime_ +=
        (clock_.elapsedTime() - t1) - (exchange_->seconds() - x1);
}


void Foam::demCoupling::particleCloud::computeForces()
{
    const label n = particles_.size();
    const voidFractionModel& vf = voidFraction_();

    fluidForce_.setSize(n);
    K_.setSize(n);
    reactingForce_.setSize(n);
    Uf_.setSize(n);
    fluidForce_ = Zero;
    K_ = 0;
    demK_.setSize(n);
    demForce_.setSize(n);
    demK_ = 0;
    demForce_ = Zero;
    reactingForce_ = Zero;
    Uf_ = Zero;

    const volScalarField& p = mesh_.lookupObject<volScalarField>("p");
    const volScalarField mu(mixture_.mu());

    // grad(p) without the capillary pressure jump (see Description)
    const volVectorField gradP
    (
        "gradPParticles",
        fvc::grad(p)
      - fvc::reconstruct(mixture_.surfaceTensionForce()*mesh_.magSf())
    );


    // Fields only some force models need
    bool needVorticity = false;
    bool needViscousStress = false;
    for (const forceModel& model : forces_)
    {
        needVorticity = needVorticity || model.needsVorticity();
        needViscousStress = needViscousStress || model.needsViscousStress();
    }

    // The fluid each particle sees: the weighted average over its cells
    // (through the model's kernel), summed over the processors that hold
    // some of them: U 3, eps, rho, mu, grad(p) 3 [, curl(U) 3, div(tau) 3]
    const List<vector> Ui(vf.sample(U_));
    const scalarList epsi(vf.sample(voidfraction_));
    const scalarList rhoi(vf.sample(rho_));
    const scalarList mui(vf.sample(mu));
    const List<vector> gradPi(vf.sample(gradP));

    List<vector> vorticityi;
    if (needVorticity)
    {
        vorticityi = vf.sample(volVectorField("curlU", fvc::curl(U_)));
    }

    List<vector> divTaui;
    if (needViscousStress)
    {
        // tau = mu (grad(U) + grad(U)^T - 2/3 div(U) I)
        const volTensorField gradU(fvc::grad(U_));
        divTaui = vf.sample
        (
            volVectorField
            (
                "divTau",
                fvc::laplacian(mu, U_) + fvc::div(mu*dev2(T(gradU)))
            )
        );
    }

    const label nq =
        9 + (needVorticity ? 3 : 0) + (needViscousStress ? 3 : 0);
    const label iVorticity = 9;
    const label iDivTau = needVorticity ? 12 : 9;

    scalarList sums(nq*n, Zero);
    forAll(particles_.position, i)
    {
        scalar* q = &sums[nq*i];
        q[0] = Ui[i].x(); q[1] = Ui[i].y(); q[2] = Ui[i].z();
        q[3] = epsi[i];
        q[4] = rhoi[i];
        q[5] = mui[i];
        q[6] = gradPi[i].x(); q[7] = gradPi[i].y(); q[8] = gradPi[i].z();
        if (needVorticity)
        {
            for (direction c = 0; c < 3; ++c)
            {
                q[iVorticity + c] = vorticityi[i][c];
            }
        }
        if (needViscousStress)
        {
            for (direction c = 0; c < 3; ++c)
            {
                q[iDivTau + c] = divTaui[i][c];
            }
        }
    }
    particles_.combine(sums, nq, combineOp::sum);

    // Forces: every processor that holds cells of a particle computes the
    // same force from the same (reduced) fluid state
    forAll(particles_.position, i)
    {
        if (vf.cells(i).empty())
        {
            continue;
        }
        const scalar* q = &sums[nq*i];
        particleFluidState s;
        s.Up = particles_.velocity[i];
        s.omega = particles_.omega[i];
        s.d = particles_.diameter[i];
        s.rhoP = particles_.density[i];
        s.Uf = vector(q[0], q[1], q[2]);
        s.eps = q[3];
        s.rhoF = q[4];
        s.muF = q[5];
        s.gradP = vector(q[6], q[7], q[8]);
        if (needVorticity)
        {
            s.vorticity =
                vector(q[iVorticity], q[iVorticity + 1], q[iVorticity + 2]);
        }
        if (needViscousStress)
        {
            s.divTau = vector(q[iDivTau], q[iDivTau + 1], q[iDivTau + 2]);
        }
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

    // The solid volume flux of the interval just run
    {
        List<vector> Vv(particles_.size());
        forAll(Vv, i)
        {
            Vv[i] = particles_.volume(i)*particles_.meanVelocity[i];
        }
        solidFlux_.primitiveFieldRef() = vf.spread(Vv);
        solidFlux_.correctBoundaryConditions();
    }

    // The fluid receives the reaction of the force the particles got. With
    // demDrag implicit that is the drag the DEM applied in the interval
    // just run, K (u - v) at every step with the DEM's K and u of it: its
    // mean is K (u - mean v), mean v the displacement over the interval
    if (implicitDemDrag_)
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

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
    const scalar dtDem = engine_->timeStep();
    const label nOld = max(label(1), label(std::round(dtOld/dtDem)));

    label n = max(label(1), label(std::floor(dt/dtDem*(1 + 1e-9))));
    if (n <= nOld && dt > dtOld*(1 + 1e-9) && (nOld + 1)*dtDem <= dtLimit)
    {
        // Growth wanted but lost to rounding: one DEM step more
        n = nOld + 1;
    }

    // Land on the end time and on write times (writeControl runTime or
    // adjustableRunTime), in whole DEM steps
    const Time& runTime = mesh_.time();
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


void Foam::demCoupling::particleCloud::sendForces()
{
    // Summed over the ranks that hold a particle: the host's only
    List<vector> hostForce(implicitDemDrag_ ? demForce_ : fluidForce_);
    scalarList hostKUf(implicitDemDrag_ ? 4*hostForce.size() : 0, Zero);
    forAll(hostForce, i)
    {
        if (particles_.hostProc[i] != Pstream::myProcNo())
        {
            hostForce[i] = Zero;
        }
        else if (implicitDemDrag_)
        {
            hostKUf[4*i] = demK_[i];
            for (direction k = 0; k < 3; ++k)
            {
                hostKUf[4*i + 1 + k] = Uf_[i][k];
            }
        }
    }
    if (implicitDemDrag_)
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


void Foam::demCoupling::particleCloud::evolve()
{
    if (!active())
    {
        return;
    }

    const dictionary& dict = couplingDict_();
    const Time& runTime = mesh_.time();

    // DEM steps in this coupling step: a whole number
    const scalar dtDem = engine_->timeStep();
    const scalar ratio = runTime.deltaTValue()/dtDem;
    demSteps_ = label(std::round(ratio));
    if (demSteps_ < 1 || mag(ratio - demSteps_) > 1e-6*ratio)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "deltaT " << runTime.deltaTValue() << " s is not a whole"
            << " number of DEM steps (timestep " << dtDem << " s in "
            << engine_->script() << "): ratio " << ratio << nl
            << "    Set deltaT to a whole multiple of the DEM timestep."
            << exit(FatalIOError);
    }
    if (!adjustTimeStep_ && demSteps_ != engine_->coupleEvery())
    {
        FatalIOErrorInFunction(dict)
            << "The DEM script " << engine_->script() << " has couple_every "
            << engine_->coupleEvery() << ", but deltaT/timestep = "
            << runTime.deltaTValue() << "/" << dtDem << " = " << demSteps_
            << " DEM steps per coupling step." << nl
            << "    Set couple_every " << demSteps_ << " in the fix couple/cfd,"
            << " or change deltaT in system/controlDict." << exit(FatalIOError);
    }

    // 0. Before the first DEM advance of a fresh start: the fluid forces of
    //    the initial state (else the first interval would run without
    //    them: a free fall of one coupling interval). A restarted DEM
    //    holds, from its restart file, the forces it had at that time.
    if (!forcesSent_ && !engine_->restarted())
    {
        computeForces();
        sendForces();
    }

    // 1. DEM advance. In parallel the DEM phase ends when its slowest rank
    //    is done: the wait for it is DEM time (LIGGGHTS's load balance),
    //    not time the exchange that follows spends in its collectives
    scalar t0 = clock_.elapsedTime();
    engine_->advance(demSteps_);
    if (Pstream::parRun())
    {
        MPI_Barrier(MPI_COMM_WORLD);
    }
    scalar t1 = clock_.elapsedTime();
    demTime_ += t1 - t0;

    // 2-4. particle data, locate, void fraction
    updateParticles();

    deletedNow_ = 0;
    if (outsidePolicy_ == "delete" && locator_->lost())
    {
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

    // How many cells a particle crosses per coupling step: above one, the
    // fluid it sees jumps (and so do its forces)
    // (the largest (|u| dt)^3/V_cell, one cube root: a cube root per
    // particle was a tenth of the coupling time)
    {
        const scalarField& V = mesh_.V();
        const scalar dt = runTime.deltaTValue();
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
        cellsPerStep_ = cbrt(returnReduce(maxCube, maxOp<scalar>()));
    }

    // 5-6. fluid at the particles, forces, fluid sources
    const scalar tf = clock_.elapsedTime();
    const scalar xf = exchange_->seconds();
    computeForces();
    forcesTime_ += (clock_.elapsedTime() - tf) - (exchange_->seconds() - xf);

    // 7. forces back to the DEM rank that owns each particle
    sendForces();

    couplingTime_ += clock_.elapsedTime() - t1;
    particleSteps_ += exchange_->nTotal();
}


void Foam::demCoupling::particleCloud::report()
{
    const Time& runTime = mesh_.time();

    if (active())
    {
        label hosted = 0;
        for (const label c : particles_.cell)
        {
            if (c >= 0) ++hosted;
        }
        reduce(hosted, sumOp<label>());

        const label nDem = exchange_->nTotal();
        Info<< "Particles: " << nDem << " in the DEM, "
            << hosted << " in the mesh, " << demSteps_ << " DEM steps,"
            << " min(voidfraction) " << gMin(voidfraction_) << endl;

        if (nDem < lastDemCount_)
        {
            Info<< "Warning: " << lastDemCount_ - nDem
                << " particle(s) left the DEM domain at t = "
                << runTime.timeName() << " s (LIGGGHTS dropped them); "
                << nDem << " remain" << endl;
        }
        lastDemCount_ = nDem;

        if (deletedNow_)
        {
            Info<< "Deleted " << deletedNow_ << " particle(s) outside the"
                << " fluid mesh at t = " << runTime.timeName() << " s ("
                << deletedTotal_ << " since the start; outsideParticles"
                << " delete)" << endl;
        }
        else if (locator_->lost())
        {
            Info<< "Warning: " << locator_->lost() << " particle(s) outside"
                << " the fluid mesh at t = " << runTime.timeName()
                << " s: no fluid force on them (outsideParticles ignore;"
                << " 'delete' removes them from the DEM)" << endl;
        }
        if (voidFraction_->floorHits())
        {
            Info<< "Warning: voidfraction floor " << voidFraction_->minVoidFraction()
                << " hit in " << voidFraction_->floorHits() << " cell(s) at"
                << " t = " << runTime.timeName() << " s ("
                << voidFraction_->totalFloorHits() << " since the start):"
                << " more particle volume than these cells hold. Use a"
                << " void-fraction model that spreads wider (virtualSphere,"
                << " diffusion) or larger cells; lowering minVoidFraction"
                << " only hides it." << endl;
        }
        if (cellsPerStep_ > 1)
        {
            Info<< "Warning: a particle crossed " << cellsPerStep_
                << " cells in one coupling step at t = " << runTime.timeName()
                << " s: the fluid it sees jumps between steps. Reduce deltaT"
                << " (fewer DEM steps per coupling step)." << endl;
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


void Foam::demCoupling::particleCloud::writeParticles() const
{
    if (!active())
    {
        return;
    }

    IDLList<passiveParticle> list;
    DynamicList<scalar> d;
    DynamicList<vector> Up, F, omega;
    DynamicList<label> id, type;
    forAll(particles_.cell, i)
    {
        if (particles_.cell[i] < 0)
        {
            continue;
        }
        list.append
        (
            new passiveParticle(mesh_, particles_.position[i], particles_.cell[i])
        );
        d.append(particles_.diameter[i]);
        Up.append(particles_.velocity[i]);
        F.append(i < fluidForce_.size() ? fluidForce_[i] : Zero);
        omega.append(particles_.omega[i]);
        id.append(particles_.tag[i]);
        type.append(particles_.type[i]);
    }

    passiveParticleCloud cloud(mesh_, "demParticles", list);
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


void Foam::demCoupling::particleCloud::writeDemRestart()
{
    if (active())
    {
        engine_->writeRestart(mesh_.time());
    }
}


void Foam::demCoupling::particleCloud::checkFinite()
{
    const volScalarField& p = mesh_.lookupObject<volScalarField>("p_rgh");
    // One reduction for the three fields; the names of the bad ones
    scalarList sums
    ({
        sumMag(U_.primitiveField()),
        sumMag(p.primitiveField()),
        sumMag(voidfraction_.primitiveField())
    });
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    const wordList names({U_.name(), p.name(), voidfraction_.name()});
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
        Time& runTime = const_cast<Time&>(mesh_.time());
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


void Foam::demCoupling::particleCloud::printTimingSplit() const
{
    const scalar total = clock_.elapsedTime() - startTime_;
    const scalar cfd = max(total - demTime_ - couplingTime_, scalar(0));

    Info<< "Timing split: DEM " << demTime_ << " s, CFD " << cfd
        << " s, coupling " << couplingTime_ << " s" << endl;

    if (active())
    {
        Info<< "Coupling split: exchange "
            << exchange_->seconds() - exchangeStart_
            << " s, locate " << locateTime_ << " s, void fraction "
            << voidFractionTime_ << " s, forces " << forcesTime_ << " s ("
            << particleSteps_ << " particle steps, "
            << 1e6*couplingTime_/max(particleSteps_, scalar(1))
            << " us per particle per coupling step)" << endl;
        if (Pstream::parRun())
        {
            const label held = particles_.size();
            Info<< "Particles held per rank at the end: min "
                << returnReduce(held, minOp<label>()) << ", max "
                << returnReduce(held, maxOp<label>()) << " (of "
                << exchange_->nTotal() << " in the DEM)" << endl;
        }
    }
}


// ************************************************************************* //
