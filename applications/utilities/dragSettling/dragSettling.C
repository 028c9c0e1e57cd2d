// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
Application
    dragSettling

Description
    Settling of one sphere from rest in still fluid, integrated (RK4) with
    the library's own force models, without a mesh:

        (m + C_vm rho_f V_p) dv/dt = (rho_p - rho_f) V_p g + F_drag(v)

    The buoyancy comes from the pressureGradient model in hydrostatic
    fluid; the drag from the model named by -drag, with eps = 1. Prints the
    terminal velocity and the time to reach 95 % of it (tau_95), or the
    whole history with -history. Used to compare the drag laws with
    measured settling (docs/forces.md); -addedMass C_vm adds the added-mass
    inertia (not a coupling force model here) to show its part in tau_95.

Usage
    dragSettling -drag DiFeliceDrag -d 0.0015 -rhoP 2560 [-rhoF 1000]
        [-mu 1e-3] [-addedMass 0.5] [-history]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "forceModel.H"
#include "mathematicalConstants.H"

using namespace Foam;
using namespace Foam::demCoupling;

int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::noBanner();
    argList::noCheckProcessorDirectories();
    argList::addNote("Single-sphere settling with the coupling's force models");
    argList::addOption("drag", "name", "drag model (a forces entry)");
    argList::addOption("d", "m", "sphere diameter");
    argList::addOption("rhoP", "kg/m3", "sphere density");
    argList::addOption("rhoF", "kg/m3", "fluid density (default 1000)");
    argList::addOption("mu", "Pa s", "fluid viscosity (default 1e-3)");
    argList::addOption("g", "m/s2", "gravity (default 9.81)");
    argList::addOption("addedMass", "C", "added-mass coefficient (default 0)");
    argList::addBoolOption("history", "print t [s] and v [m/s] every step");

    argList args(argc, argv, false, false, false);

    if (!args.found("drag") || !args.found("d") || !args.found("rhoP"))
    {
        FatalErrorInFunction
            << "Options -drag, -d and -rhoP are required" << exit(FatalError);
    }
    const word dragName(args.get<word>("drag"));
    const scalar d = args.get<scalar>("d");
    const scalar rhoP = args.get<scalar>("rhoP");
    const scalar rhoF = args.getOrDefault<scalar>("rhoF", 1000);
    const scalar mu = args.getOrDefault<scalar>("mu", 1e-3);
    const scalar g = args.getOrDefault<scalar>("g", 9.81);
    const scalar Cvm = args.getOrDefault<scalar>("addedMass", 0);

    if (d <= 0 || rhoP <= rhoF || mu <= 0 || rhoF <= 0 || Cvm < 0)
    {
        FatalErrorInFunction
            << "Need d > 0, rhoP > rhoF > 0, mu > 0, addedMass >= 0"
            << exit(FatalError);
    }

    dictionary dict;
    autoPtr<forceModel> drag(forceModel::New(dragName, dict));
    autoPtr<forceModel> buoyancy(forceModel::New("pressureGradient", dict));

    const scalar Vp = constant::mathematical::pi/6*pow3(d);
    const scalar inertia = (rhoP + Cvm*rhoF)*Vp;

    particleFluidState s;
    s.d = d;
    s.rhoP = rhoP;
    s.rhoF = rhoF;
    s.muF = mu;
    s.eps = 1;
    s.gradP = vector(0, 0, -rhoF*g);       // hydrostatic, z up

    // dv/dt of the vertical velocity v (negative: falling)
    auto accel = [&](const scalar v)
    {
        s.Up = vector(0, 0, v);
        const scalar F =
            drag->force(s).total(s).z() + buoyancy->force(s).total(s).z();
        return (F - rhoP*Vp*g)/inertia;
    };

    // Step: a small fraction of the Stokes relaxation time
    const scalar tauStokes = (rhoP + Cvm*rhoF)*sqr(d)/(18*mu);
    const scalar dt = tauStokes/2000;

    const bool history = args.found("history");
    if (history)
    {
        Info<< "# t [s]  v [m/s] (downward)" << nl;
    }

    DynamicList<scalar> times, speeds;
    scalar t = 0, v = 0;
    times.append(t);
    speeds.append(0);
    for (label step = 0; step < 100000000; ++step)
    {
        const scalar k1 = accel(v);
        const scalar k2 = accel(v + 0.5*dt*k1);
        const scalar k3 = accel(v + 0.5*dt*k2);
        const scalar k4 = accel(v + dt*k3);
        const scalar dv = dt/6*(k1 + 2*k2 + 2*k3 + k4);
        v += dv;
        t += dt;
        times.append(t);
        speeds.append(-v);
        if (history && step % 20 == 0)
        {
            Info<< t << ' ' << -v << nl;
        }
        if (mag(dv) < 1e-13*mag(v) && t > 10*tauStokes)
        {
            break;
        }
    }

    const scalar vTerminal = speeds.last();
    scalar tau95 = t;
    forAll(speeds, i)
    {
        if (speeds[i] >= 0.95*vTerminal)
        {
            tau95 = times[i];
            break;
        }
    }

    Info<< (history ? "# " : "") << "drag " << dragName << " d " << d
        << " rhoP " << rhoP << " rhoF " << rhoF << " mu " << mu
        << " addedMass " << Cvm << " vTerminal " << vTerminal
        << " tau95 " << tau95 << " Re " << rhoF*vTerminal*d/mu << endl;

    return 0;
}
