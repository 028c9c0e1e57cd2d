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
    const particleData& particles
)
{
    forAll(particles.cell, i)
    {
        const label c = particles.cell[i];
        if (c < 0)
        {
            cells_[i].clear();
            weights_[i].clear();
        }
        else
        {
            cells_[i] = labelList(1, c);
            weights_[i] = scalarList(1, 1.0);
        }
    }
}
