// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "caseInputCheck.H"

template<class Type>
void Foam::demCoupling::caseInputCheck::initialField
(
    const GeometricField<Type, fvPatchField, volMesh>& fld,
    const scalar maxMag
)
{
    // The first bad cell of this rank (-1: none), then over the ranks
    label bad = -1;
    scalar badMag = 0;
    forAll(fld, c)
    {
        const scalar m = mag(fld[c]);
        if (!std::isfinite(m) || (maxMag > 0 && m > maxMag))
        {
            bad = c;
            badMag = m;
            break;
        }
    }
    forAll(fld.boundaryField(), patchi)
    {
        for (const Type& v : fld.boundaryField()[patchi])
        {
            const scalar m = mag(v);
            if (bad < 0 && (!std::isfinite(m) || (maxMag > 0 && m > maxMag)))
            {
                bad = labelMax;     // on a boundary
                badMag = m;
            }
        }
    }
    const bool anyBad = returnReduce(bad >= 0, orOp<bool>());
    if (!anyBad)
    {
        return;
    }
    if (bad >= 0)
    {
        FatalErrorInFunction
            << "The initial field " << fld.name() << " ("
            << fld.objectPath() << ") has |" << fld.name() << "| = "
            << badMag;
        if (bad == labelMax)
        {
            FatalError << " on a boundary";
        }
        else
        {
            FatalError << " in cell " << bad;
        }
        FatalError << ": every value must be finite";
        if (maxMag > 0)
        {
            FatalError
                << " and at most " << maxMag << " m/s (above it neither"
                << " water nor air is incompressible)";
        }
        FatalError << exit(FatalError);
    }
    // (the other ranks go on until the reporting rank's FatalError ends
    // them all)
}


// ************************************************************************* //
