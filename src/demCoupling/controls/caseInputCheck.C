// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "caseInputCheck.H"
#include "inputCheck.H"
#include "IFstream.H"
#include "IOdictionary.H"
#include "Switch.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::scalar Foam::demCoupling::caseInputCheck::gMax = 2000;

const Foam::scalar Foam::demCoupling::caseInputCheck::UMax = 1000;


namespace
{

// A dimensioned scalar of a dictionary (written "nu 1e-06;" or with its
// dimensions) that must be > 0
void requirePositive
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::dimensionSet& dims,
    const char* what
)
{
    using namespace Foam;
    const scalar v = dimensionedScalar(key, dims, dict).value();
    if (!(v > 0) || !std::isfinite(v))
    {
        demCoupling::inputCheck::notAllowed(dict, key, v, what);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::demCoupling::caseInputCheck::controlDict(const argList& args)
{
    const fileName file
    (
        args.rootPath()/args.globalCaseName()/"system"/"controlDict"
    );
    if (!isFile(file))
    {
        return;     // Time says what is missing
    }
    IFstream is(file);
    const dictionary dict(is);

    inputCheck::get<scalar>
    (
        dict, "deltaT", &inputCheck::positive, "> 0 (the time step, s)"
    );
    if (dict.found("writeInterval"))
    {
        inputCheck::get<scalar>
        (
            dict, "writeInterval", &inputCheck::positive,
            "> 0 (time steps or seconds between writes, by writeControl)"
        );
    }
    if (dict.getOrDefault<Switch>("adjustTimeStep", false))
    {
        for (const word key : {"maxCo", "maxAlphaCo", "maxDeltaT"})
        {
            if (dict.found(key))
            {
                inputCheck::get<scalar>
                (
                    dict, key, &inputCheck::positive,
                    "> 0 (with adjustTimeStep the step follows it)"
                );
            }
        }
    }
}


void Foam::demCoupling::caseInputCheck::transportProperties
(
    const Time& runTime
)
{
    const IOdictionary tp
    (
        IOobject
        (
            "transportProperties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );

    // One fluid (pimpleDemFoam) or the phases of a VoF mixture
    List<const dictionary*> fluids;
    if (tp.found("phases"))
    {
        for (const word& phase : tp.get<wordList>("phases"))
        {
            fluids.append(&tp.subDict(phase));
        }
        if (tp.found("sigma") && !tp.isDict("sigma"))
        {
            const scalar sigma =
                dimensionedScalar("sigma", dimForce/dimLength, tp).value();
            if (!(sigma >= 0) || !std::isfinite(sigma))
            {
                inputCheck::notAllowed
                (
                    tp, "sigma", sigma, ">= 0 (surface tension, N/m)"
                );
            }
        }
    }
    else
    {
        fluids.append(&tp);
    }

    for (const dictionary* d : fluids)
    {
        if (d->found("rho"))
        {
            requirePositive(*d, "rho", dimDensity, "> 0 (density, kg/m3)");
        }
        if
        (
            d->getOrDefault<word>("transportModel", "Newtonian") == "Newtonian"
         && d->found("nu")
        )
        {
            requirePositive
            (
                *d, "nu", dimViscosity, "> 0 (kinematic viscosity, m2/s)"
            );
        }
    }
}


void Foam::demCoupling::caseInputCheck::gravity
(
    const uniformDimensionedVectorField& g
)
{
    const scalar magG = mag(g.value());
    if (!std::isfinite(magG) || magG > gMax)
    {
        FatalErrorInFunction
            << "Gravity g = " << g.value() << " in " << g.objectPath()
            << ": |g| = " << magG << " m/s2 must be finite and at most "
            << gMax << " m/s2 (200 times the Earth's 9.81, the most a"
            << " geotechnical centrifuge applies to a model dam)"
            << exit(FatalError);
    }
}


// ************************************************************************* //
