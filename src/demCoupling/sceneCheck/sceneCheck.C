// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "sceneCheck.H"
#include "volFields.H"
#include "demEngine.H"
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
    const dictionary& couplingDict,
    const sceneMaps& maps
)
:
    mesh_(mesh),
    couplingDict_(couplingDict),
    maps_(maps)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::label Foam::demCoupling::sceneCheck::run
(
    demEngine& engine,
    const scalar targetErrorPercent,
    const scalar velocity
)
{
    using constant::mathematical::pi;
    failures_.clear();
    warnings_.clear();

    const Time& runTime = mesh_.time();
    const word model(couplingDict_.get<word>("voidFraction"));
    // The settings checked as the solver checks them (unknown names,
    // missing or out-of-range coefficients stop here, naming the file)
    voidFractionModel::New(couplingDict_, mesh_);
    forceModel::NewList(couplingDict_);
    const word scheme(couplingDict_.getOrDefault<word>("demDrag", "implicit"));

    particleData p;
    engine.ownedParticles(p);
    const label n = p.size();

    scalar rhoF = 0, muF = 0;
    fluidProperties(mesh_, rhoF, muF);
    const uniformDimensionedVectorField g
    (
        IOobject
        (
            "g", runTime.constant(), mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    const scalar gMag = mag(g.value());

    Info<< nl << "Scene check of " << runTime.path() << nl
        << "    maps: " << maps_.dir() << " (meshStudy.dat,"
        << " stability/stabilityMap.dat, stability/dragStability.dat)" << nl
        << "    fluid the particles sit in: rho " << rhoF << " kg/m3, mu "
        << muF << " Pa s; voidFraction " << model << ", demDrag " << scheme
        << nl << endl;

    if (n == 0)
    {
        warnings_.append
        (
            "the DEM script sets up no particle (it inserts them later):"
            " sizes, the Rayleigh time and tau_p are not checked"
        );
    }

    // Sizes against the cells
    const scalarField& V = mesh_.V();
    DynamicList<scalar> d, dOverDx, dxOverD, rhoP, dxOf;
    label outside = 0;
    for (label i = 0; i < n; ++i)
    {
        const label c = mesh_.findCell(p.position[i]);
        if (c < 0)
        {
            ++outside;
            continue;
        }
        const scalar dx = cbrt(V[c]);
        d.append(p.diameter[i]);
        rhoP.append(p.density[i]);
        dxOf.append(dx);
        dOverDx.append(p.diameter[i]/dx);
        dxOverD.append(dx/p.diameter[i]);
    }
    const label nIn = d.size();
    scalarList cellSizes(mesh_.nCells());
    forAll(cellSizes, c)
    {
        cellSizes[c] = cbrt(V[c]);
    }
    const scalar dxMedian = quantile(cellSizes, 0.5);

    Info<< "    particles         " << n << " (" << outside
        << " outside the mesh)";
    if (nIn)
    {
        Info<< ", d " << fig(quantile(d, 0)) << " .. " << fig(quantile(d, 1))
            << " m, median " << fig(quantile(d, 0.5)) << " m, density "
            << fig(quantile(rhoP, 0.5)) << " kg/m3";
    }
    Info<< nl << "    cells             " << mesh_.nCells() << ", dx = cbrt(V) "
        << fig(quantile(cellSizes, 0)) << " .. "
        << fig(quantile(cellSizes, 1)) << " m, median " << fig(dxMedian)
        << " m" << endl;
    if (outside)
    {
        warnings_.append
        (
            std::to_string(outside) + " particle(s) lie outside the mesh"
            " (no fluid force on them)"
        );
    }

    scalar dxdMin = -1, dxdMedian = -1;
    if (nIn)
    {
        dxdMin = quantile(dxOverD, 0);
        dxdMedian = quantile(dxOverD, 0.5);
        Info<< "    d/dx              min " << fig(quantile(dOverDx, 0))
            << ", median " << fig(quantile(dOverDx, 0.5)) << ", max "
            << fig(quantile(dOverDx, 1)) << " (dx/d " << fig(dxdMin)
            << " .. " << fig(quantile(dxOverD, 1)) << ")" << endl;
        if (model == "virtualSphere")
        {
            const scalar c =
                couplingDict_.subDict("virtualSphereCoeffs")
               .get<scalar>("sizeThreshold");
            label under = 0;
            forAll(d, i)
            {
                if (d[i] <= c*dxOf[i])
                {
                    ++under;
                }
            }
            Info<< "    virtual sphere    " << under << " of " << nIn
                << " particles at or under its threshold d = " << c
                << " dx (they take the centre model)" << endl;
        }
    }

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

    // The coupling step against the particle response time
    const bool adjustable =
        runTime.controlDict().getOrDefault<bool>("adjustTimeStep", false);
    // the longest coupling step the run may take
    const scalar maxDeltaT =
        runTime.controlDict().getOrDefault<scalar>("maxDeltaT", GREAT);
    const scalar dt =
        adjustable && maxDeltaT < GREAT ? maxDeltaT : runTime.deltaTValue();
    if (adjustable && maxDeltaT >= GREAT)
    {
        warnings_.append
        (
            "adjustTimeStep without maxDeltaT: the coupling step is"
            " unbounded; checked at the first deltaT, " + fig(dt) + " s"
        );
    }
    if (nIn)
    {
        List<scalar> tau(nIn);
        forAll(tau, i)
        {
            tau[i] = rhoP[i]*sqr(d[i])/(18*muF);
        }
        const scalar tauMin = quantile(tau, 0);
        const word scene("settling");
        scalar stable = 0;
        const scalar blowUp = maps_.dragBlowUp(scheme, scene, stable);
        Info<< "    coupling step     " << dt << " s"
            << (adjustable && maxDeltaT < GREAT ? " (maxDeltaT)" : "") << " = "
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
                " (docs/stability/dragStability.dat); the largest step"
                " measured stable below it is " + fig(stable) + " tau_p = "
                + fig(stable*tauMin) + " s"
            );
        }

        // Particle Courant number at the expected speed
        scalar v = velocity;
        std::string why(" (given)");
        if (v <= 0)
        {
            // terminal velocity of the median particle, eps = 1, in still
            // hydrostatic fluid, with the case's force models (buoyancy
            // only if pressureGradient is one): F(v) = rho_p V_p g
            PtrList<forceModel> forces(forceModel::NewList(couplingDict_));
            particleFluidState s;
            s.d = quantile(d, 0.5);
            s.rhoP = quantile(rhoP, 0.5);
            s.rhoF = rhoF;
            s.muF = muF;
            s.eps = 1;
            s.gradP = vector(0, 0, -rhoF*gMag);
            const scalar weight = s.rhoP*pi/6*pow3(s.d)*gMag;
            auto resistance = [&](const scalar speed)
            {
                s.Up = vector(0, 0, -speed);
                scalar F = 0;
                forAll(forces, k)
                {
                    F += forces[k].force(s).total(s).z();
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
                    " particle Courant number is not checked (give"
                    " -velocity)"
                );
            }
            else if (hi >= 1e4)
            {
                warnings_.append
                (
                    "no terminal velocity below 1e4 m/s with the case's"
                    " force models (no drag?): the particle Courant number"
                    " is not checked (give -velocity)"
                );
            }
            else
            {
                scalar lo = 0;
                for (label it = 0; it < 200; ++it)
                {
                    const scalar mid = 0.5*(lo + hi);
                    (resistance(mid) < weight ? lo : hi) = mid;
                }
                v = 0.5*(lo + hi);
                why = " (terminal velocity of the median particle)";
            }
        }
        if (v > 0)
        {
            const scalar Co = v*dt/dxMedian;
            Info<< "    particle Courant  " << fig(Co) << " at " << fig(v)
                << " m/s" << why.c_str() << ": cells crossed per coupling step"
                << endl;
            if (Co > 1)
            {
                warnings_.append
                (
                    "a particle at " + fig(v) + " m/s crosses " + fig(Co)
                  + " cells per coupling step (the fluid it sees jumps);"
                    " use deltaT at most " + fig(dxMedian/v) + " s"
                );
            }
        }
    }

    // The void-fraction models at this scene's cell size
    if (nIn)
    {
        Info<< nl << "    Void-fraction models: expected settling error at"
            << " the median dx/d " << fig(dxdMedian)
            << ", stability at the smallest " << fig(dxdMin) << nl
            << "      model           expected error   stable (measured at"
            << " dx/d)   cost vs virtualSphere" << endl;
        word cheapest;
        scalar cheapestCost = GREAT;
        for (const word& m : maps_.models())
        {
            bool inRange = true;
            const scalar err = maps_.expectedError(m, dxdMedian, inRange);
            scalar at = 0;
            const int ok = maps_.bounded(m, dxdMin, at);
            const scalar cost = maps_.relativeCost(m, dxdMedian);
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
            if (m == model)
            {
                if (ok == 0)
                {
                    failures_.append
                    (
                        "voidFraction " + m + ": its stability run failed at"
                        " dx/d = " + fig(at) + " (docs/stability/"
                        "stabilityMap.dat), and this scene's largest particle"
                        " has dx/d = " + fig(dxdMin)
                    );
                }
                if (err > targetErrorPercent)
                {
                    const scalar need =
                        maps_.smallestDxOverD(m, targetErrorPercent);
                    warnings_.append
                    (
                        "voidFraction " + m + ": expected settling error "
                      + fig(err, 2) + " % above the target "
                      + fig(targetErrorPercent, 2) + " %"
                      + (need > 0
                          ? "; it reaches the target with cells of dx/d >= "
                            + fig(need) + " (dx >= " + fig(need*quantile(d, 0.5))
                            + " m for the median particle)"
                          : std::string())
                    );
                }
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
    return failures_.size();
}


// ************************************************************************* //
