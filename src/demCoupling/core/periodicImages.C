// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
    interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
    Licence: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "periodicImages.H"
#include "meshReach.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "Pstream.H"
#include "SubField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::periodicImages::periodicImages(const polyMesh& mesh)
:
    shifts_(),
    bounds_(mesh.points(), false)
{
    bounds_.reduce();

    // Translations seen on this processor
    List<vector> found;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (pp.empty())
        {
            continue;
        }
        vector t(Zero);
        if (isA<processorCyclicPolyPatch>(pp))
        {
            const auto& pc = refCast<const processorCyclicPolyPatch>(pp);
            if (!pc.parallel())
            {
                continue;
            }
            t = pc.neighbFaceCentres()[0] - pc.faceCentres()[0];
        }
        else if (isA<cyclicPolyPatch>(pp))
        {
            const auto& cp = refCast<const cyclicPolyPatch>(pp);
            if (!cp.parallel())
            {
                continue;
            }
            t = cp.neighbPatch().faceCentres()[0] - cp.faceCentres()[0];
        }
        else
        {
            continue;
        }
        found.append(t);
    }

    // Every processor's, one of each (t and -t are the same translation)
    List<List<vector>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = found;
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    const scalar span = mag(bounds_.span());
    const scalar tol = reachTolerance*max(span, SMALL);
    DynamicList<vector> basis;
    for (const List<vector>& l : all)
    {
        for (const vector& t : l)
        {
            if (mag(t) <= tol)
            {
                continue;
            }
            bool known = false;
            for (const vector& b : basis)
            {
                known = known || mag(t - b) <= tol || mag(t + b) <= tol;
            }
            if (!known)
            {
                basis.append(t);
            }
        }
    }
    if (basis.size() > 3)
    {
        FatalErrorInFunction
            << "More than three periodic translations in the mesh: " << basis
            << exit(FatalError);
    }

    // Combinations: each translation -1, 0 or +1 times, not all 0
    label n = 1;
    for (label k = 0; k < basis.size(); ++k)
    {
        n *= 3;
    }
    for (label code = 0; code < n; ++code)
    {
        vector s(Zero);
        label c = code;
        bool zero = true;
        forAll(basis, k)
        {
            const label a = c % 3 - 1;
            c /= 3;
            s += scalar(a)*basis[k];
            zero = zero && a == 0;
        }
        if (!zero)
        {
            shifts_.append(s);
        }
    }
}


// ************************************************************************* //
