#include "momentumCouplingModel.H"

namespace Foam
{
namespace demCoupling
{
    defineTypeNameAndDebug(momentumCouplingModel, 0);
    defineRunTimeSelectionTable(momentumCouplingModel, dictionary);
}
}


Foam::demCoupling::momentumCouplingModel::momentumCouplingModel
(
    const dictionary&,
    const fvMesh& mesh
)
:
    mesh_(mesh)
{}


Foam::autoPtr<Foam::demCoupling::momentumCouplingModel>
Foam::demCoupling::momentumCouplingModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType(dict.get<word>("momentumCoupling"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "momentumCoupling",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "Momentum coupling: " << modelType << endl;

    return autoPtr<momentumCouplingModel>(cstrIter()(dict, mesh));
}


// ************************************************************************* //
