// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "fluidSampler.H"
#include "fvc.H"
#include "interpolationCellPoint.H"
#include "gravityMeshObject.H"
#include "inputCheck.H"
#include "couplingKeywords.H"

const Foam::Enum<Foam::demCoupling::fluidSampler::velocitySource>
Foam::demCoupling::fluidSampler::velocitySourceNames
({
    { velocitySource::voidFractionAverage, "voidFractionAverage" },
    { velocitySource::cellPoint, "cellPoint" },
    { velocitySource::grainTop, "grainTop" },
    { velocitySource::bedSurfaceLogLaw, "bedSurfaceLogLaw" },
    { velocitySource::roughnessLayer, "roughnessLayer" },
});

namespace
{

// The keywords of couplingProperties the sampler reads
const Foam::demCoupling::couplingKeywords::declare keywords
(
    {
        "fluidVelocity", "velocityFluctuation", "bedSurfaceLogLawCoeffs",
        "roughnessLayerCoeffs"
    }
);

// Writes scalars and vectors one after the other into a buffer slot, or
// reads them back in the same order
struct slot
{
    Foam::scalar* q;

    void put(const Foam::scalar v) { *q++ = v; }
    void put(const Foam::vector& v) { put(v.x()); put(v.y()); put(v.z()); }
};

struct readSlot
{
    const Foam::scalar* q;

    Foam::scalar scalar() { return *q++; }
    Foam::vector vector()
    {
        const Foam::vector v(q[0], q[1], q[2]);
        q += 3;
        return v;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::fluidSampler::fluidSampler
(
    const dictionary& dict,
    const fvMesh& mesh,
    const PtrList<forceModel>& forces
)
:
    velocity_(velocitySource::voidFractionAverage),
    logLaw_(),
    fluctuation_(),
    up_(0, 0, 1),
    dictName_(dict.name()),
    needVorticity_(false),
    needViscousStress_(false),
    needTopAndBottom_(false)
{
    for (const forceModel& model : forces)
    {
        needVorticity_ = needVorticity_ || model.needsVorticity();
        needViscousStress_ = needViscousStress_ || model.needsViscousStress();
        needTopAndBottom_ =
            needTopAndBottom_ || model.needsTopAndBottomVelocity();
    }

    velocity_ = inputCheck::selectOrDefault
    (
        dict, "fluidVelocity", velocitySourceNames,
        velocitySource::voidFractionAverage,
        "voidFractionAverage (the void-fraction model's weighted average"
        " over the particle's cells; the default), cellPoint"
        " (interpolated at the particle's centre in its host cell) and"
        " grainTop (reconstructed at the particle's top, d/2 above its"
        " centre against gravity) and bedSurfaceLogLaw (the rough-bed log"
        " law in the cell that holds the bed's surface, over the"
        " particle's exposed part; bedSurfaceLogLawCoeffs) and"
        " roughnessLayer (that law above the bed's crests and the"
        " roughness layer's linear profile between them;"
        " roughnessLayerCoeffs)"
    );
    if (velocity_ == velocitySource::cellPoint)
    {
        Info<< "Fluid velocity at each particle: cell-point interpolation"
            << " at its centre (fluidVelocity cellPoint)" << endl;
    }
    if (velocity_ == velocitySource::grainTop)
    {
        Info<< "Fluid velocity at each particle: at its top, d/2 above its"
            << " centre against gravity, reconstructed linearly in its host"
            << " cell and bounded by its neighbours (fluidVelocity grainTop)"
            << endl;
    }
    if (velocity_ == velocitySource::bedSurfaceLogLaw)
    {
        logLaw_.reset(new bedSurfaceLogLaw(dict));
        Info<< "Fluid velocity at each particle: the rough-bed log law in"
            << " its host cell (k_s " << logLaw_->roughness() << " d), over"
            << " the bed's zero plane (the solids of the host cell and the"
            << " cell below packed at solid fraction "
            << logLaw_->bedSolidFraction() << "), anchored to the velocity"
            << " of the cell above, averaged over the particle's exposed"
            << " part (fluidVelocity bedSurfaceLogLaw, Wiberg & Smith 1987)"
            << endl;
    }
    else if (velocity_ == velocitySource::roughnessLayer)
    {
        roughnessLayerLogLaw* layer = new roughnessLayerLogLaw(dict);
        logLaw_.reset(layer);
        Info<< "Fluid velocity at each particle: the rough-bed log law"
            << " (k_s " << layer->roughness() << " D, D "
            << layer->roughnessDiameter() << " m) over the bed's zero plane"
            << " (solid fraction " << layer->bedSolidFraction() << ") down"
            << " to the crests " << layer->crestAboveZeroPlane() << " D"
            << " above it, linear from there to the troughs "
            << layer->layerDepth() << " D below the crests, anchored to the"
            << " velocity of the cell above, averaged over the particle's"
            << " exposed part (fluidVelocity roughnessLayer, Nikora et al."
            << " 2004)" << endl;
    }
    // Each log law's coefficients are read only with its model
    for
    (
        const velocitySource withCoeffs
      : {velocitySource::bedSurfaceLogLaw, velocitySource::roughnessLayer}
    )
    {
        const word model(velocitySourceNames[withCoeffs]);
        if (velocity_ != withCoeffs && dict.found(model + "Coeffs"))
        {
            FatalIOErrorInFunction(dict)
                << model << "Coeffs in " << dict.name() << " is read only"
                << " with fluidVelocity " << model << " (this run's is "
                << velocitySourceNames[velocity_] << "): remove it, or set"
                << " fluidVelocity " << model << exit(FatalIOError);
        }
    }
    const bool needUp =
        velocity_ == velocitySource::grainTop
     || velocity_ == velocitySource::bedSurfaceLogLaw
     || velocity_ == velocitySource::roughnessLayer
     || needTopAndBottom_
     || dict.found("velocityFluctuation");
    if (needUp)
    {
        // The solver's gravity (constant/g, read once per run)
        const vector g(meshObjects::gravity::New(mesh.time()).value());
        if (mag(g) < SMALL)
        {
            FatalIOErrorInFunction(dict)
                << (
                       velocity_ != velocitySource::voidFractionAverage
                     && velocity_ != velocitySource::cellPoint
                     ? "fluidVelocity "
                     + velocitySourceNames[velocity_]
                     : needTopAndBottom_
                     ? "A force model that takes the velocity at a grain's"
                       " top and bottom (WibergSmithLift)"
                     : "velocityFluctuation"
                   )
                << " in " << dict.name() << " needs gravity (constant/g,"
                << " not zero): a grain's top and the fluctuations'"
                << " vertical direction are against it" << exit(FatalIOError);
        }
        up_ = -g/mag(g);
    }
    if (dict.found("velocityFluctuation"))
    {
        fluctuation_.reset(new velocityFluctuation(dict));
        if (fluctuation_->fromTurbulence())
        {
            Info<< "Turbulent velocity fluctuations seen by the particles:"
                << " from the turbulence model's k and epsilon at each"
                << " particle (eddy-interaction model, Gosman & Ioannides"
                << " 1983: streamwise r.m.s. "
                << velocityFluctuation::streamwisePerSqrtK << " sqrt(k),"
                << " lateral " << velocityFluctuation::lateralRatio
                << " and vertical " << velocityFluctuation::verticalRatio
                << " of it; velocityFluctuation source turbulence); eddy"
                << " lifetime "
                << velocityFluctuation::eddyLifetimeModelNames
                   [
                       fluctuation_->eddyLifetime()
                   ]
                << " ("
                << velocityFluctuation::lifetimeFormula
                   (
                       fluctuation_->eddyLifetime()
                   )
                << ")" << endl;
            if (fluctuation_->sampledAtTop() || fluctuation_->sampledAbove())
            {
                Info<< "    k, epsilon"
                    << (fluctuation_->sizedByShearStress() ? " and the shear"
                        " stress" : "")
                    << (
                           fluctuation_->sampledAtTop()
                         ? " taken at each particle's top, d/2 above its"
                           " centre (sampledAt grainTop)"
                         : " taken in the cell above each particle's host"
                           " cell (sampledAt cellAbove)"
                       )
                    << endl;
            }
            if (fluctuation_->sizedByShearStress())
            {
                Info<< "    sized by the local Reynolds shear stress"
                    << " (size shearStress): streamwise r.m.s. "
                    << velocityFluctuation::streamwisePerFrictionVelocity
                    << " sqrt(nut sqrt(2 S:S)), Nezu & Nakagawa's near-bed"
                    << " r.m.s. per friction velocity, instead of "
                    << velocityFluctuation::streamwisePerSqrtK << " sqrt(k)"
                    << endl;
            }
        }
        else
        {
            Info<< "Turbulent velocity fluctuations seen by the particles:"
                << " streamwise r.m.s. " << fluctuation_->intensity()
                << " |U|, lateral " << velocityFluctuation::lateralRatio
                << " and vertical " << velocityFluctuation::verticalRatio
                << " of it, a new eddy every " << fluctuation_->eddyTime()
                << " s (velocityFluctuation)" << endl;
        }
    }

}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::label Foam::demCoupling::fluidSampler::width() const
{
    // Uf, eps, rhoF, muF, gradP [, UfAverage] [, vorticity] [, divTau]
    // [, k, epsilon] [, shear] [, UfTop, UfBottom]
    return 9 + (velocityAtPoint() ? 3 : 0)
      + (needVorticity_ ? 3 : 0) + (needViscousStress_ ? 3 : 0)
      + (turbulenceFluctuations() ? 2 : 0) + (sizedByShearStress() ? 1 : 0)
      + (needTopAndBottom_ ? 6 : 0);
}


void Foam::demCoupling::fluidSampler::pack
(
    const particleFluidState& s,
    scalar* q
) const
{
    slot out{q};
    out.put(s.Uf);
    out.put(s.eps);
    out.put(s.rhoF);
    out.put(s.muF);
    out.put(s.gradP);
    if (velocityAtPoint())
    {
        out.put(s.UfAverage);
    }
    if (needVorticity_)
    {
        out.put(s.vorticity);
    }
    if (needViscousStress_)
    {
        out.put(s.divTau);
    }
    if (turbulenceFluctuations())
    {
        out.put(s.kTurb);
        out.put(s.epsilonTurb);
    }
    if (sizedByShearStress())
    {
        out.put(s.shearTurb);
    }
    if (needTopAndBottom_)
    {
        out.put(s.UfTop);
        out.put(s.UfBottom);
    }
}


void Foam::demCoupling::fluidSampler::unpack
(
    const scalar* q,
    particleFluidState& s
) const
{
    readSlot in{q};
    s.Uf = in.vector();
    s.eps = in.scalar();
    s.rhoF = in.scalar();
    s.muF = in.scalar();
    s.gradP = in.vector();
    s.UfAverage = s.Uf;
    if (velocityAtPoint())
    {
        s.UfAverage = in.vector();
    }
    if (needVorticity_)
    {
        s.vorticity = in.vector();
    }
    if (needViscousStress_)
    {
        s.divTau = in.vector();
    }
    if (turbulenceFluctuations())
    {
        s.kTurb = in.scalar();
        s.epsilonTurb = in.scalar();
    }
    if (sizedByShearStress())
    {
        s.shearTurb = in.scalar();
    }
    if (needTopAndBottom_)
    {
        s.UfTop = in.vector();
        s.UfBottom = in.vector();
    }
}


void Foam::demCoupling::fluidSampler::sampleBedSurfaceLogLaw
(
    const volVectorField& U,
    const volScalarField& voidfraction,
    const particleData& particles,
    List<vector>& values
) const
{
    const fvMesh& mesh = U.mesh();
    const PtrList<Field<vector>> acrossU(valuesAcrossCoupledPatches(U));
    const PtrList<Field<scalar>> acrossEps
    (
        valuesAcrossCoupledPatches(voidfraction)
    );
    sampleOnHost
    (
        particles, values,
        [&](const label i)
        {
            const label celli = particles.cell[i];
            scalar zLow, zHigh;
            bedSurfaceLogLaw::verticalExtent(mesh, celli, up_, zLow, zHigh);
            // A wall below (no face neighbour, no coupled patch) bounds
            // the bed: it counts as a packed cell
            const scalar solidBelow =
                1
              - valueInCellAbove
                (
                    voidfraction, acrossEps, celli, -up_,
                    1 - logLaw_->bedSolidFraction()
                );
            return logLaw_->velocity
            (
                particles.position[i] & up_,
                particles.diameter[i],
                zLow,
                zHigh,
                1 - voidfraction[celli],
                solidBelow,
                valueInCellAbove(U, acrossU, celli, up_),
                U[celli],
                // the top of the domain counts as clear fluid
                1 - valueInCellAbove(voidfraction, acrossEps, celli, up_, 1.0)
            );
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::demCoupling::fluidSampler::faceAbove
(
    const fvMesh& mesh,
    const label celli,
    const vector& up
)
{
    label upFace = -1;
    scalar mostUp = -GREAT;
    for (const label facei : mesh.cells()[celli])
    {
        vector n(mesh.faceAreas()[facei]);
        if (mesh.faceOwner()[facei] != celli)
        {
            n = -n;
        }
        const scalar c = (n & up)/(mag(n) + VSMALL);
        if (c > mostUp)
        {
            mostUp = c;
            upFace = facei;
        }
    }
    return upFace;
}


Foam::List<Foam::demCoupling::particleFluidState>
Foam::demCoupling::fluidSampler::sample
(
    const voidFractionModel& vf,
    const fluidView& fluid,
    const volScalarField& voidfraction,
    const particleData& particles,
    const particleCombine& combine
) const
{
    const label n = particles.size();
    List<particleFluidState> states(n);

    if (turbulenceFluctuations() && !fluid.turbulent())
    {
        FatalErrorInFunction
            << "velocityFluctuation source turbulence in " << dictName_
            << " needs a turbulence model with the fluid fraction in its"
            << " equations: simulationType RAS or LES in"
            << " constant/turbulenceProperties (this run is laminar)." << nl
            << "    For a laminar run give the fluctuations' size and"
            << " lifetime: source fixed; intensity ...; eddyTime ...;"
            << exit(FatalError);
    }

    // This processor's part of each particle's weighted averages
    {
        const volVectorField& U = fluid.U();
        List<vector> Ui(vf.sample(U));
        if (velocityAtPoint())
        {
            forAll(states, i)
            {
                states[i].UfAverage = Ui[i];
            }
        }
        // grad(U), once per step, for whichever of grainTop, the viscous
        // stress and the shear stress needs it
        tmp<volTensorField> tgradU;
        if
        (
            velocity_ == velocitySource::grainTop || needTopAndBottom_
         || needViscousStress_ || sizedByShearStress()
        )
        {
            tgradU = fvc::grad(U);
        }
        List<vector> top;
        if (needTopAndBottom_)
        {
            // At the top and the bottom of each grain, by its host
            // processor (a grain no processor hosts keeps the average)
            top = Ui;
            List<vector> bottom(Ui);
            sampleAtHeight(U, tgradU(), particles, 0.5, top);
            sampleAtHeight(U, tgradU(), particles, -0.5, bottom);
            forAll(states, i)
            {
                states[i].UfTop = top[i];
                states[i].UfBottom = bottom[i];
            }
        }
        if (velocity_ == velocitySource::grainTop)
        {
            if (needTopAndBottom_)
            {
                // The top, sampled above from the same averages
                Ui = top;
            }
            else
            {
                sampleAtHeight(U, tgradU(), particles, 0.5, Ui);
            }
        }
        else if
        (
            velocity_ == velocitySource::bedSurfaceLogLaw
         || velocity_ == velocitySource::roughnessLayer
        )
        {
            sampleBedSurfaceLogLaw(U, voidfraction, particles, Ui);
        }
        else if (velocity_ == velocitySource::cellPoint)
        {
            // At the centre, by the host processor alone
            const interpolationCellPoint<vector> atPoint(U);
            sampleOnHost
            (
                particles, Ui,
                [&](const label i)
                {
                    return atPoint.interpolate
                    (
                        particles.position[i],
                        particles.cell[i]
                    );
                }
            );
        }
        const scalarList epsi(vf.sample(voidfraction));
        const scalarList rhoi(vf.sample(fluid.rho()));
        const scalarList mui(vf.sample(fluid.mu()()));
        const List<vector> gradPi(vf.sample(fluid.gradP()()));
        forAll(states, i)
        {
            states[i].Uf = Ui[i];
            states[i].eps = epsi[i];
            states[i].rhoF = rhoi[i];
            states[i].muF = mui[i];
            states[i].gradP = gradPi[i];
        }
        if (needVorticity_)
        {
            const List<vector> w
            (
                vf.sample(volVectorField("curlU", fvc::curl(U)))
            );
            forAll(states, i)
            {
                states[i].vorticity = w[i];
            }
        }
        if (needViscousStress_)
        {
            // tau = mu (grad(U) + grad(U)^T - 2/3 div(U) I)
            const volScalarField mu(fluid.mu());
            const volTensorField& gradU = tgradU();
            const List<vector> divTau
            (
                vf.sample
                (
                    volVectorField
                    (
                        "divTau",
                        fvc::laplacian(mu, U) + fvc::div(mu*dev2(T(gradU)))
                    )
                )
            );
            forAll(states, i)
            {
                states[i].divTau = divTau[i];
            }
        }
        const bool turbulenceAtTop =
            fluctuation_.valid() && fluctuation_->sampledAtTop();
        const bool turbulenceAbove =
            fluctuation_.valid() && fluctuation_->sampledAbove();
        if (turbulenceFluctuations())
        {
            const tmp<volScalarField> tk(fluid.k());
            const tmp<volScalarField> tepsilon(fluid.epsilon());
            scalarList ki(vf.sample(tk()));
            scalarList epsiloni(vf.sample(tepsilon()));
            if (turbulenceAbove)
            {
                sampleInCellAbove(tk(), particles, ki);
                sampleInCellAbove(tepsilon(), particles, epsiloni);
            }
            if (turbulenceAtTop)
            {
                sampleAtHeight(tk(), fvc::grad(tk())(), particles, 0.5, ki);
                sampleAtHeight
                (
                    tepsilon(), fvc::grad(tepsilon())(), particles, 0.5,
                    epsiloni
                );
            }
            forAll(states, i)
            {
                states[i].kTurb = ki[i];
                states[i].epsilonTurb = epsiloni[i];
            }
        }
        if (sizedByShearStress())
        {
            // The Reynolds shear stress over rho, nut sqrt(2 S:S)
            // (nut |du/dz| in a shear flow)
            const volScalarField shear
            (
                "reynoldsShearStress",
                fluid.nut()*sqrt(2.0)*mag(symm(tgradU()))
            );
            scalarList sheari(vf.sample(shear));
            if (turbulenceAbove)
            {
                sampleInCellAbove(shear, particles, sheari);
            }
            if (turbulenceAtTop)
            {
                sampleAtHeight
                (
                    shear, fvc::grad(shear)(), particles, 0.5, sheari
                );
            }
            forAll(states, i)
            {
                states[i].shearTurb = sheari[i];
            }
        }
    }

    // Summed over the processors that hold cells of a particle
    const label w = width();
    scalarList sums(w*n, Zero);
    forAll(states, i)
    {
        pack(states[i], &sums[w*i]);
    }
    combine.combine(sums, w, combineOp::sum);
    forAll(states, i)
    {
        particleFluidState& s = states[i];
        unpack(&sums[w*i], s);
        s.Up = particles.velocity[i];
        s.omega = particles.omega[i];
        s.d = particles.diameter[i];
        s.rhoP = particles.density[i];
        if (needTopAndBottom_)
        {
            s.up = up_;
        }
    }

    // Turbulent fluctuations, from the combined (same on every processor)
    // velocity
    if (fluctuation_.valid())
    {
        const scalar t = voidfraction.time().value();
        forAll(states, i)
        {
            particleFluidState& s = states[i];
            const vector uPrime
            (
                fluctuation_->fromTurbulence()
              ? fluctuation_->turbulent
                (
                    particles.tag[i], t, s.Uf, up_, s.kTurb, s.epsilonTurb,
                    mag(s.Uf - s.Up), s.shearTurb
                )
              : (*fluctuation_)(particles.tag[i], t, s.Uf, up_)
            );
            s.Uf += uPrime;
            // The same eddy passes over the grain's top and bottom
            s.UfTop += uPrime;
            s.UfBottom += uPrime;
        }
    }
    return states;
}
