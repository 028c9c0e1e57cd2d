// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "envelopeCholeskyPreconditioner.H"
#include "HashTable.H"
#include "inputCheck.H"
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
    //- The kept factors, one per field name and mesh (its addressing)
    Foam::HashTable
    <
        std::shared_ptr<const Foam::demCoupling::envelopeCholesky>
    >& keptFactors()
    {
        static Foam::HashTable
        <
            std::shared_ptr<const Foam::demCoupling::envelopeCholesky>
        > kept;
        return kept;
    }

    Foam::label factorisationCount = 0;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::shared_ptr<const Foam::demCoupling::envelopeCholesky>
Foam::demCoupling::envelopeCholeskyPreconditioner::factorOf
(
    const lduMatrix::solver& sol,
    const dictionary& controls
)
{
    auto& kept = keptFactors();
    const word& name = sol.fieldName();
    const word key
    (
        name + "@" + Foam::name(&sol.matrix().lduAddr()),
        false
    );

    auto iter = kept.find(key);
    if (iter.found() && iter.val()->sameMatrix(sol))
    {
        return iter.val();
    }

    // The preconditioner's own dictionary (empty when it is given as a
    // word): its keywords checked, the limit > 0
    inputCheck::keywords(controls, {"preconditioner", "maxEnvelopePerCell"});
    const scalar maxEnvelopePerCell = inputCheck::getOrDefault<scalar>
    (
        controls, "maxEnvelopePerCell", 2000, &inputCheck::positive,
        "> 0 (entries of the factor per cell, a memory limit)"
    );

    std::shared_ptr<const envelopeCholesky> factor
    (
        std::make_shared<const envelopeCholesky>(sol, maxEnvelopePerCell)
    );
    ++factorisationCount;

    Info<< "envelopeCholesky: factorised the matrix of " << name << ": "
        << sol.matrix().diag().size() << " cells, " << factor->envelopeSize()
        << " entries in the envelope" << endl;

    kept.set(key, factor);
    return factor;
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
    factor_->solve(wA, rA);
}
