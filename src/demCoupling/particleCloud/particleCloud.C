#include "particleCloud.H"
#include "incompressibleTwoPhaseMixture.H"
#include "zeroGradientFvPatchFields.H"
#include "Time.H"

namespace
{
// Open constant/couplingProperties if the case has one
Foam::autoPtr<Foam::IOdictionary> readCouplingDict(const Foam::fvMesh& mesh)
{
    using namespace Foam;

    IOobject io
    (
        "couplingProperties",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );

    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        return nullptr;
    }
    return autoPtr<IOdictionary>::New(io);
}
}


Foam::demCoupling::particleCloud::particleCloud
(
    const fvMesh& mesh,
    const volVectorField& U,
    const volScalarField& rho,
    const incompressibleTwoPhaseMixture& mixture
)
:
    mesh_(mesh),
    couplingDict_(readCouplingDict(mesh)),
    voidfraction_
    (
        IOobject
        (
            "voidfraction",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1),
        zeroGradientFvPatchScalarField::typeName
    ),
    Us_
    (
        IOobject
        (
            "Us",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    Ksl_
    (
        IOobject
        (
            "Ksl",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimDensity/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    fExplicit_
    (
        IOobject
        (
            "fExplicit",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedVector(dimForce/dimVolume, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    particles_(),
    clock_(),
    demTime_(0),
    couplingTime_(0),
    startTime_(clock_.elapsedTime())
{
    // Keep the previous time level of eps for d(eps)/dt
    voidfraction_.oldTime();

    if (!active())
    {
        Info<< "No constant/couplingProperties: no particles, the fluid"
            << " volume fraction stays 1 (plain two-phase VoF)." << nl
            << endl;
        return;
    }

    FatalIOErrorInFunction(couplingDict_())
        << "This build of libdemCoupling has no DEM engine yet: the coupling"
        << " to LIGGGHTS is not available." << nl
        << "    Remove " << couplingDict_().objectPath()
        << " to run without particles." << exit(FatalIOError);
}


void Foam::demCoupling::particleCloud::evolve()
{
    if (!active())
    {
        return;
    }
}


void Foam::demCoupling::particleCloud::report() const
{}


void Foam::demCoupling::particleCloud::printTimingSplit() const
{
    const scalar total = clock_.elapsedTime() - startTime_;
    const scalar cfd = max(total - demTime_ - couplingTime_, scalar(0));

    Info<< "Timing split: DEM " << demTime_ << " s, CFD " << cfd
        << " s, coupling " << couplingTime_ << " s" << endl;
}
