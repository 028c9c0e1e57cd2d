// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "centre.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(centre, 0);
    addToRunTimeSelectionTable(voidFractionModel, centre, dictionary);
}
}
}


Foam::demCoupling::voidFractionModels::centre::centre
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(dict, mesh)
{}


void Foam::demCoupling::voidFractionModels::centre::distribute
(
    const particleData& particles,
    const particleCombine& combine
)
{
    forAll(particles.cell, i)
    {
        const label c = particles.cell[i];
        if (c >= 0)
        {
            addCell(i, c, 1.0);
        }
    }
}
