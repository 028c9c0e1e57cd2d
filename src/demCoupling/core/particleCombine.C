// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "particleCombine.H"
#include "Pstream.H"
#include "ops.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::demCoupling::particleCombine::identity
(
    const combineOp op
)
{
    return op == combineOp::sum ? 0
         : op == combineOp::min ? GREAT
         : -GREAT;
}


void Foam::demCoupling::particleCombine::combine
(
    scalarList& values,
    const label width,
    const combineOp op
) const
{
    if (!Pstream::parRun())
    {
        return;   // one rank holds every particle: nothing to combine
    }
    // Every rank holds the same whole list
    switch (op)
    {
        case combineOp::sum:
            Pstream::listCombineGather(values, plusEqOp<scalar>());
            break;
        case combineOp::min:
            Pstream::listCombineGather(values, minEqOp<scalar>());
            break;
        case combineOp::max:
            Pstream::listCombineGather(values, maxEqOp<scalar>());
            break;
    }
    Pstream::listCombineScatter(values);
}


void Foam::demCoupling::particleCombine::combine
(
    labelList& values,
    const combineOp op
) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    scalarList v(values.size());
    forAll(values, i)
    {
        v[i] = values[i];
    }
    combine(v, 1, op);
    forAll(values, i)
    {
        values[i] = label(v[i]);
    }
}


// ************************************************************************* //
