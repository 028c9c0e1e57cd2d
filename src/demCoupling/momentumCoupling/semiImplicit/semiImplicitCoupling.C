#include "semiImplicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace momentumCouplingModels
{
    defineTypeNameAndDebug(semiImplicitCoupling, 0);
    addToRunTimeSelectionTable
    (
        momentumCouplingModel,
        semiImplicitCoupling,
        dictionary
    );
}
}
}


Foam::demCoupling::momentumCouplingModels::semiImplicitCoupling::
semiImplicitCoupling
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    momentumCouplingModel(dict, mesh)
{}


void Foam::demCoupling::momentumCouplingModels::semiImplicitCoupling::assemble
(
    const particleData& particles,
    const voidFractionModel& voidFraction,
    const scalarList& K,
    const List<vector>&,
    const List<vector>& Fexplicit,
    volScalarField& Ksl,
    volVectorField& Us,
    volVectorField& fExplicit
) const
{
    const scalarField& V = mesh_.V();

    scalarField KV(mesh_.nCells(), 0);          // sum w K
    vectorField KVv(mesh_.nCells(), Zero);      // sum w K v
    scalarField solidVolume(mesh_.nCells(), 0);
    vectorField momentum(mesh_.nCells(), Zero);

    fExplicit.primitiveFieldRef() = Zero;

    forAll(particles.cell, i)
    {
        if (voidFraction.cells(i).empty())
        {
            continue;   // none of its cells on this processor
        }
        const scalar Vp = particles.volume(i);
        const labelList& cells = voidFraction.cells(i);
        const scalarList& w = voidFraction.weights(i);
        forAll(cells, k)
        {
            const label c = cells[k];
            KV[c] += w[k]*K[i];
            KVv[c] += w[k]*K[i]*particles.velocity[i];
            fExplicit[c] -= w[k]*Fexplicit[i]/V[c];
            solidVolume[c] += w[k]*Vp;
            momentum[c] += w[k]*Vp*particles.velocity[i];
        }
    }

    forAll(Ksl, c)
    {
        Ksl[c] = KV[c]/V[c];
        if (KV[c] > 0)
        {
            Us[c] = KVv[c]/KV[c];
        }
        else if (solidVolume[c] > 0)
        {
            Us[c] = momentum[c]/solidVolume[c];
        }
        else
        {
            Us[c] = Zero;
        }
    }

    Ksl.correctBoundaryConditions();
    Us.correctBoundaryConditions();
    fExplicit.correctBoundaryConditions();
}


// ************************************************************************* //
