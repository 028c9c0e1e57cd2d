#include "explicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace momentumCouplingModels
{
    defineTypeNameAndDebug(explicitCoupling, 0);
    addToRunTimeSelectionTable
    (
        momentumCouplingModel,
        explicitCoupling,
        dictionary
    );
}
}
}


Foam::demCoupling::momentumCouplingModels::explicitCoupling::explicitCoupling
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    momentumCouplingModel(dict, mesh)
{}


void Foam::demCoupling::momentumCouplingModels::explicitCoupling::assemble
(
    const particleData& particles,
    const voidFractionModel& voidFraction,
    const scalarList& K,
    const List<vector>& Uf,
    const List<vector>& Fexplicit,
    volScalarField& Ksl,
    volVectorField& Us,
    volVectorField& fExplicit
) const
{
    const scalarField& V = mesh_.V();

    scalarField solidVolume(mesh_.nCells(), 0);
    vectorField momentum(mesh_.nCells(), Zero);

    Ksl.primitiveFieldRef() = 0;
    fExplicit.primitiveFieldRef() = Zero;

    forAll(particles.cell, i)
    {
        if (voidFraction.cells(i).empty())
        {
            continue;   // none of its cells on this processor
        }
        const vector Fi
        (
            K[i]*(Uf[i] - particles.velocity[i]) + Fexplicit[i]
        );
        const scalar Vp = particles.volume(i);
        const labelList& cells = voidFraction.cells(i);
        const scalarList& w = voidFraction.weights(i);
        forAll(cells, k)
        {
            const label c = cells[k];
            fExplicit[c] -= w[k]*Fi/V[c];
            solidVolume[c] += w[k]*Vp;
            momentum[c] += w[k]*Vp*particles.velocity[i];
        }
    }

    forAll(Us, c)
    {
        Us[c] = solidVolume[c] > 0 ? momentum[c]/solidVolume[c] : Zero;
    }

    Ksl.correctBoundaryConditions();
    Us.correctBoundaryConditions();
    fExplicit.correctBoundaryConditions();
}


// ************************************************************************* //
