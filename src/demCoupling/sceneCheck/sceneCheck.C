// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "sceneCheck.H"
#include "volFields.H"
#include "demEngine.H"
#include "couplingControls.H"
#include "forceModel.H"
#include "voidFractionModel.H"
#include "IOdictionary.H"
#include "uniformDimensionedFields.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;

// x to p significant digits (a word: written without quotes)
Foam::word fig(const scalar x, const int p = 3)
{
    std::ostringstream os;
    os << std::setprecision(p) << x;
    return Foam::word(os.str(), false);
}

// The q-quantile of v (0: min, 0.5: median, 1: max)
scalar quantile(Foam::List<scalar> v, const scalar q)
{
    if (v.empty())
    {
        return 0;
    }
    std::sort(v.begin(), v.end());
    const Foam::label i =
        Foam::min(Foam::label(q*(v.size() - 1) + 0.5), v.size() - 1);
    return v[i];
}

// The fluid the particles sit in: the densest phase of a two-phase
// transportProperties (phases (water air)), else its nu and rho
void fluidProperties(const Foam::fvMesh& mesh, scalar& rho, scalar& mu)
{
    using namespace Foam;
    const IOdictionary tp
    (
        IOobject
        (
            "transportProperties", mesh.time().constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    rho = -1;
    mu = -1;
    if (tp.found("phases"))
    {
        for (const word& phase : tp.get<wordList>("phases"))
        {
            const dictionary& d = tp.subDict(phase);
            const scalar r = dimensionedScalar("rho", dimDensity, d).value();
            if (r > rho)
            {
                rho = r;
                mu = r*dimensionedScalar("nu", dimViscosity, d).value();
            }
        }
    }
    else
    {
        rho = dimensionedScalar("rho", dimDensity, tp).value();
        mu = rho*dimensionedScalar("nu", dimViscosity, tp).value();
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::demCoupling::sceneCheck::sceneCheck
(
    const fvMesh& mesh,
    const sceneMaps& maps,
    const couplingControls& controls,
    const voidFractionModel& voidFraction,
    const PtrList<forceModel>& forces
)
:
    mesh_(mesh),
    maps_(maps),
    controls_(controls),
    voidFraction_(voidFraction),
    forces_(forces),
    rhoF_(0),
    muF_(0),
    gMag_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::demCoupling::sceneCheck::readFluid()
{
    fluidProperties(mesh_, rhoF_, muF_);
    const uniformDimensionedVectorField g
    (
        IOobject
        (
            "g", mesh_.time().constant(), mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    gMag_ = mag(g.value());
}


void Foam::demCoupling::sceneCheck::checkSizes
(
    const particleData& p,
    sceneParticles& s
)
{
    // Sizes against the cells
    const scalarField& V = mesh_.V();
    for (label i = 0; i < p.size(); ++i)
    {
        const label c = mesh_.findCell(p.position[i]);
        if (c < 0)
        {
            ++s.outside;
            continue;
        }
        const scalar dx = cbrt(V[c]);
        s.d.append(p.diameter[i]);
        s.rhoP.append(p.density[i]);
        s.dx.append(dx);
        s.dOverDx.append(p.diameter[i]/dx);
        s.dxOverD.append(dx/p.diameter[i]);
    }
    scalarList cellSizes(mesh_.nCells());
    forAll(cellSizes, c)
    {
        cellSizes[c] = cbrt(V[c]);
    }
    s.dxMedian = quantile(cellSizes, 0.5);

    Info<< "    particles         " << p.size() << " (" << s.outside
        << " outside the mesh)";
    if (s.in())
    {
        Info<< ", d " << fig(quantile(s.d, 0)) << " .. "
            << fig(quantile(s.d, 1)) << " m, median "
            << fig(quantile(s.d, 0.5)) << " m, density "
            << fig(quantile(s.rhoP, 0.5)) << " kg/m3";
    }
    Info<< nl << "    cells             " << mesh_.nCells() << ", dx = cbrt(V) "
        << fig(quantile(cellSizes, 0)) << " .. "
        << fig(quantile(cellSizes, 1)) << " m, median " << fig(s.dxMedian)
        << " m" << endl;
    if (s.outside)
    {
        warnings_.append
        (
            std::to_string(s.outside) + " particle(s) lie outside the mesh"
            " (no fluid force on them)"
        );
    }

    if (!s.in())
    {
        return;
    }
    s.dxdMin = quantile(s.dxOverD, 0);
    s.dxdMedian = quantile(s.dxOverD, 0.5);
    Info<< "    d/dx              min " << fig(quantile(s.dOverDx, 0))
        << ", median " << fig(quantile(s.dOverDx, 0.5)) << ", max "
        << fig(quantile(s.dOverDx, 1)) << " (dx/d " << fig(s.dxdMin)
        << " .. " << fig(quantile(s.dxOverD, 1)) << ")" << endl;
    const scalar c = voidFraction_.sizeThreshold();
    if (c > 0)
    {
        label under = 0;
        forAll(s.d, i)
        {
            if (s.d[i] <= c*s.dx[i])
            {
                ++under;
            }
        }
        Info<< "    virtual sphere    " << under << " of " << s.in()
            << " particles at or under its threshold d = " << c
            << " dx (they take the centre model)" << endl;
    }
}


void Foam::demCoupling::sceneCheck::checkDemStep(const demEngine& engine)
{
    // DEM step against the Rayleigh time
    const scalar dtDem = engine.timeStep();
    scalar dMin = 0, EMin = 0;
    const scalar tR = engine.rayleighTime(dMin, EMin);
    if (tR > 0 && tR < GREAT)
    {
        const scalar share = dtDem/tR;
        Info<< "    DEM step          " << dtDem << " s = " << fig(100*share)
            << " % of the Rayleigh time " << fig(tR) << " s (d " << dMin
            << " m; limit 20 %)" << endl;
        if (share > 0.2)
        {
            warnings_.append
            (
                "the DEM step is " + fig(100*share) + " % of the Rayleigh"
                " time (above 20 %: contacts under-resolved); use at most "
                + fig(0.2*tR) + " s"
            );
        }
    }
    else
    {
        Info<< "    DEM step          " << dtDem << " s (Rayleigh time not"
            << " known: no particles or no youngsModulus/poissonsRatio)"
            << endl;
    }
}


Foam::scalar Foam::demCoupling::sceneCheck::longestCouplingStep(bool& bounded)
{
    // The coupling step against the particle response time: the longest
    // step the run may take
    const Time& runTime = mesh_.time();
    const bool adjustable =
        runTime.controlDict().getOrDefault<bool>("adjustTimeStep", false);
    const scalar maxDeltaT =
        runTime.controlDict().getOrDefault<scalar>("maxDeltaT", GREAT);
    bounded = adjustable && maxDeltaT < GREAT;
    const scalar dt = bounded ? maxDeltaT : runTime.deltaTValue();
    if (adjustable && maxDeltaT >= GREAT)
    {
        warnings_.append
        (
            "adjustTimeStep without maxDeltaT: the coupling step is"
            " unbounded; checked at the first deltaT, " + fig(dt) + " s"
        );
    }
    return dt;
}


void Foam::demCoupling::sceneCheck::checkCouplingStep
(
    const sceneParticles& s,
    const scalar dt,
    const bool fromMaxDeltaT
)
{
    List<scalar> tau(s.in());
    forAll(tau, i)
    {
        tau[i] = s.rhoP[i]*sqr(s.d[i])/(18*muF_);
    }
    const scalar tauMin = quantile(tau, 0);
    const word scene("settling");
    const word& scheme = controls_.demDragName();
    scalar stable = 0;
    const scalar blowUp = maps_.dragBlowUp(scheme, scene, stable);
    Info<< "    coupling step     " << dt << " s"
        << (fromMaxDeltaT ? " (maxDeltaT)" : "") << " = "
        << fig(dt/tauMin) << " tau_p of the most responsive particle ("
        << fig(tauMin) << " s); " << scheme << " DEM drag blew up at "
        << (blowUp < GREAT ? fig(blowUp) + " tau_p (settling)"
                           : std::string("no measured dt/tau_p")).c_str()
        << endl;
    if (dt/tauMin >= blowUp)
    {
        failures_.append
        (
            "the coupling step is " + fig(dt/tauMin) + " tau_p: the "
            + scheme + " DEM drag blew up at " + fig(blowUp)
            + " tau_p in the measured settling scene"
            " (etc/sceneMaps/dragStability.dat); the largest step"
            " measured stable below it is " + fig(stable) + " tau_p = "
            + fig(stable*tauMin) + " s"
        );
    }
}


Foam::scalar Foam::demCoupling::sceneCheck::terminalVelocity
(
    const sceneParticles& s,
    std::string& why
)
{
    using constant::mathematical::pi;

    // The terminal velocity of the median particle, eps = 1, in still
    // hydrostatic fluid, with the case's force models (buoyancy only if
    // pressureGradient is one): F(v) = rho_p V_p g
    particleFluidState state;
    state.d = quantile(s.d, 0.5);
    state.rhoP = quantile(s.rhoP, 0.5);
    state.rhoF = rhoF_;
    state.muF = muF_;
    state.eps = 1;
    state.gradP = vector(0, 0, -rhoF_*gMag_);
    const scalar weight = state.rhoP*pi/6*pow3(state.d)*gMag_;
    auto resistance = [&](const scalar speed)
    {
        state.Up = vector(0, 0, -speed);
        scalar F = 0;
        forAll(forces_, k)
        {
            F += forces_[k].force(state).total(state).z();
        }
        return F;
    };
    scalar hi = 1e-3;
    while (resistance(hi) < weight && hi < 1e4)
    {
        hi *= 2;
    }
    if (resistance(0) >= weight)
    {
        why = " (the median particle floats: no settling velocity)";
        warnings_.append
        (
            "the median particle does not settle in the fluid: the"
            " particle Courant number is not checked (give -velocity)"
        );
        return -1;
    }
    if (hi >= 1e4)
    {
        warnings_.append
        (
            "no terminal velocity below 1e4 m/s with the case's force models"
            " (no drag?): the particle Courant number is not checked (give"
            " -velocity)"
        );
        return -1;
    }
    scalar lo = 0;
    for (label it = 0; it < 200; ++it)
    {
        const scalar mid = 0.5*(lo + hi);
        (resistance(mid) < weight ? lo : hi) = mid;
    }
    why = " (terminal velocity of the median particle)";
    return 0.5*(lo + hi);
}


void Foam::demCoupling::sceneCheck::checkCourant
(
    const sceneParticles& s,
    const scalar dt,
    const scalar velocity
)
{
    // Particle Courant number at the expected speed
    std::string why(" (given)");
    const scalar v = velocity > 0 ? velocity : terminalVelocity(s, why);
    if (v <= 0)
    {
        return;
    }
    const scalar Co = v*dt/s.dxMedian;
    Info<< "    particle Courant  " << fig(Co) << " at " << fig(v)
        << " m/s" << why.c_str() << ": cells crossed per coupling step"
        << endl;
    if (Co > 1)
    {
        warnings_.append
        (
            "a particle at " + fig(v) + " m/s crosses " + fig(Co)
          + " cells per coupling step (the fluid it sees jumps);"
            " use deltaT at most " + fig(s.dxMedian/v) + " s"
        );
    }
}


void Foam::demCoupling::sceneCheck::compareModels
(
    const sceneParticles& s,
    const scalar targetErrorPercent
)
{
    // The void-fraction models at this scene's cell size
    const word& model = voidFraction_.type();
    Info<< nl << "    Void-fraction models: expected settling error at"
        << " the median dx/d " << fig(s.dxdMedian)
        << ", stability at the smallest " << fig(s.dxdMin) << nl
        << "      model           expected error   stable (measured at"
        << " dx/d)   cost vs virtualSphere" << endl;
    word cheapest;
    scalar cheapestCost = GREAT;
    for (const word& m : maps_.models())
    {
        bool inRange = true;
        const scalar err = maps_.expectedError(m, s.dxdMedian, inRange);
        scalar at = 0;
        const int ok = maps_.bounded(m, s.dxdMin, at);
        const scalar cost = maps_.relativeCost(m, s.dxdMedian);
        std::ostringstream row;
        row << "    " << (m == model ? "* " : "  ") << std::left
            << std::setw(16) << m << std::setw(17)
            << (fig(err, 2) + " %" + (inRange ? "" : " (out of range)"))
            << std::setw(24)
            << (std::string(ok == 1 ? "yes" : ok == 0 ? "NO" : "unknown")
              + " (" + fig(at) + ")")
            << (cost > 0 ? fig(cost, 2) : std::string("-"));
        Info<< row.str().c_str() << endl;
        if (ok != 0 && err <= targetErrorPercent && cost > 0 && cost < cheapestCost)
        {
            cheapestCost = cost;
            cheapest = m;
        }
        if (m != model)
        {
            continue;
        }
        if (ok == 0)
        {
            failures_.append
            (
                "voidFraction " + m + ": its stability run failed at"
                " dx/d = " + fig(at) + " (etc/sceneMaps/stabilityMap.dat),"
                " and this scene's largest particle has dx/d = "
              + fig(s.dxdMin)
            );
        }
        if (err > targetErrorPercent)
        {
            const scalar need = maps_.smallestDxOverD(m, targetErrorPercent);
            warnings_.append
            (
                "voidFraction " + m + ": expected settling error "
              + fig(err, 2) + " % above the target "
              + fig(targetErrorPercent, 2) + " %"
              + (need > 0
                  ? "; it reaches the target with cells of dx/d >= "
                    + fig(need) + " (dx >= " + fig(need*quantile(s.d, 0.5))
                    + " m for the median particle)"
                  : std::string())
            );
        }
    }
    if (!cheapest.empty())
    {
        Info<< "    cheapest model within " << fig(targetErrorPercent, 2)
            << " % here: " << cheapest << " (cost "
            << fig(cheapestCost, 2) << " of the virtual sphere's)" << endl;
    }
    else
    {
        Info<< "    no model is measured within " << fig(targetErrorPercent, 2)
            << " % at this cell size" << endl;
    }
}


void Foam::demCoupling::sceneCheck::checkBedload(const scalar shields)
{
    // The case's turbulence: laminar, or its RAS/LES model
    const IOdictionary tp
    (
        IOobject
        (
            "turbulenceProperties", mesh_.time().constant(), mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    const word type(tp.get<word>("simulationType"));
    word model("laminar");
    if (type != "laminar")
    {
        model = tp.subDict(type).get<word>(type + "Model");
    }

    scalar lamBelow = 0, lamOnset = 0;
    if (!maps_.bedloadOnset("laminar", lamBelow, lamOnset))
    {
        warnings_.append
        (
            "no measured laminar onset of bedload in the maps"
            " (bedloadOnset.dat): the bed's Shields number is not checked"
        );
        return;
    }
    // The lowest onset measured with a turbulence model
    word turbModel;
    scalar turbBelow = GREAT, turbOnset = GREAT;
    for (const word& m : maps_.onsetModels())
    {
        scalar b = 0, o = 0;
        if (m != "laminar" && maps_.bedloadOnset(m, b, o) && o < turbOnset)
        {
            turbModel = m;
            turbBelow = b;
            turbOnset = o;
        }
    }
    Info<< "    bed Shields       " << fig(shields) << " (given); bedload"
        << " starts between " << fig(lamBelow) << " and " << fig(lamOnset)
        << " laminar";
    if (!turbModel.empty())
    {
        Info<< ", between " << fig(turbBelow) << " and " << fig(turbOnset)
            << " with " << turbModel.c_str();
    }
    Info<< " (the bedload channel, cells of 2 d); this case: "
        << model.c_str() << endl;

    const bool laminar = (model == "laminar");
    if (shields <= min(lamBelow, turbBelow))
    {
        Info<< "    -> laminar flow is enough: no measured model moves a bed"
            << " at theta " << fig(shields) << (laminar ? "" : " (the"
            " turbulence model costs CFD time and moves no grain either)")
            << endl;
    }
    else if (laminar && !turbModel.empty() && shields > turbBelow
          && shields <= lamBelow)
    {
        warnings_.append
        (
            "the bed's Shields number " + fig(shields) + " lies between the"
            " turbulent onset of bedload (" + fig(turbBelow) + "-"
          + fig(turbOnset) + ", " + turbModel + ") and the laminar one ("
          + fig(lamBelow) + "-" + fig(lamOnset) + "): a laminar run moves"
            " no grain where a turbulent one does; use simulationType RAS,"
            " RASModel " + turbModel + " (constant/turbulenceProperties)"
            " with the grain-side model that onset was measured with, the"
            " bedload tutorial's default (constant/couplingProperties:"
            " velocityFluctuation { source turbulence; eddyLifetime"
            " turnover; size shearStress; sampledAt cellAbove; },"
            " fluidVelocity grainTop, WibergSmithLift with liftCoefficient"
            " 0.2, virtualSphere diameterRatio 2, voidFractionFloor spill;"
            " docs/erosion.md)"
        );
    }
    else if (shields <= lamBelow)
    {
        Info<< "    -> a turbulence model is needed to move this bed (this"
            << " case has one; its onset was measured with the bedload"
            << " tutorial's grain-side model: eddies of the cell above,"
            << " the velocity at the grain's top, bed lift, a virtual sphere"
            << " of 2 d, the floor spilled; with other grain-side options"
            << " it lies higher, docs/erosion.md)" << endl;
    }
    else
    {
        Info<< "    -> above the laminar onset: both move the bed (the"
            << " turbulent flux is larger; docs/erosion.md)" << endl;
    }
}


void Foam::demCoupling::sceneCheck::printVerdict() const
{
    Info<< nl << "Verdict:" << endl;
    for (const string& s : failures_)
    {
        Info<< "    FAIL  " << s.c_str() << endl;
    }
    for (const string& s : warnings_)
    {
        Info<< "    WARN  " << s.c_str() << endl;
    }
    if (failures_.empty() && warnings_.empty())
    {
        Info<< "    ok    no setting in a measured failure region, the"
            << " expected error within the target" << endl;
    }
    else if (failures_.empty())
    {
        Info<< "    ok    no setting in a measured failure region" << endl;
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::label Foam::demCoupling::sceneCheck::run
(
    demEngine& engine,
    const scalar targetErrorPercent,
    const scalar velocity,
    const scalar shields
)
{
    failures_.clear();
    warnings_.clear();

    particleData p;
    engine.ownedParticles(p);
    readFluid();

    Info<< nl << "Scene check of " << mesh_.time().path() << nl
        << "    maps: " << maps_.dir() << " (meshStudy.dat,"
        << " stabilityMap.dat, dragStability.dat)" << nl
        << "    fluid the particles sit in: rho " << rhoF_ << " kg/m3, mu "
        << muF_ << " Pa s; voidFraction " << voidFraction_.type()
        << ", demDrag " << controls_.demDragName() << nl << endl;

    if (p.size() == 0)
    {
        warnings_.append
        (
            "the DEM script sets up no particle (it inserts them later):"
            " sizes, the Rayleigh time and tau_p are not checked"
        );
    }

    sceneParticles s;
    checkSizes(p, s);
    checkDemStep(engine);
    bool fromMaxDeltaT = false;
    const scalar dt = longestCouplingStep(fromMaxDeltaT);
    if (s.in())
    {
        checkCouplingStep(s, dt, fromMaxDeltaT);
        checkCourant(s, dt, velocity);
        compareModels(s, targetErrorPercent);
    }
    if (shields > 0)
    {
        Info<< endl;
        checkBedload(shields);
    }
    printVerdict();
    return failures_.size();
}


// ************************************************************************* //
