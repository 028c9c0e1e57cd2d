// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "envelopeCholeskyPreconditioner.H"
#include "HashPtrTable.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace demCoupling
{
    defineTypeNameAndDebug(envelopeCholeskyPreconditioner, 0);

    lduMatrix::preconditioner::
        addsymMatrixConstructorToTable<envelopeCholeskyPreconditioner>
        addenvelopeCholeskyPreconditionerSymMatrixConstructorToTable_;
}
}


namespace
{
    //- The kept factors, one per field name
    Foam::HashPtrTable<Foam::demCoupling::envelopeCholesky>& keptFactors()
    {
        static Foam::HashPtrTable<Foam::demCoupling::envelopeCholesky> kept;
        return kept;
    }

    Foam::label factorisationCount = 0;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::demCoupling::envelopeCholesky&
Foam::demCoupling::envelopeCholeskyPreconditioner::factorOf
(
    const lduMatrix::solver& sol,
    const dictionary& controls
)
{
    HashPtrTable<envelopeCholesky>& kept = keptFactors();
    const word& name = sol.fieldName();

    auto iter = kept.find(name);
    if (iter.found() && iter.val()->sameMatrix(sol))
    {
        return *iter.val();
    }
    kept.erase(name);

    const scalar maxEnvelopePerCell =
        controls.lookupOrDefault<scalar>("maxEnvelopePerCell", 2000);

    autoPtr<envelopeCholesky> factor(new envelopeCholesky(sol));
    ++factorisationCount;

    const label nCells = sol.matrix().diag().size();
    if (factor->envelopeSize() > maxEnvelopePerCell*max(nCells, label(1)))
    {
        const label size = factor->envelopeSize();
        FatalIOErrorInFunction(controls)
            << "The envelopeCholesky preconditioner of " << name
            << " would keep " << size << " entries for " << nCells
            << " cells (" << scalar(size)/max(nCells, label(1))
            << " per cell), more than maxEnvelopePerCell "
            << maxEnvelopePerCell << ". Use preconditioner DIC, or GAMG, "
            << "for " << name << " in system/fvSolution, or raise "
            << "maxEnvelopePerCell in its preconditioner dictionary"
            << exit(FatalIOError);
    }

    Info<< "envelopeCholesky: factorised the matrix of " << name << ": "
        << nCells << " cells, " << factor->envelopeSize()
        << " entries in the envelope" << endl;

    const envelopeCholesky& made = *factor;
    kept.set(name, factor);
    return made;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::envelopeCholeskyPreconditioner::
envelopeCholeskyPreconditioner
(
    const lduMatrix::solver& sol,
    const dictionary& controls
)
:
    lduMatrix::preconditioner(sol),
    factor_(factorOf(sol, controls))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label
Foam::demCoupling::envelopeCholeskyPreconditioner::nFactorisations()
{
    return factorisationCount;
}


void Foam::demCoupling::envelopeCholeskyPreconditioner::precondition
(
    solveScalarField& wA,
    const solveScalarField& rA,
    const direction
) const
{
    factor_.solve(wA, rA);
}
