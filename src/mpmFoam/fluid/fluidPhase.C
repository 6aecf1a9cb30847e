#include "fluidPhase.H"
#include "constrainHbyA.H"
#include "constrainPressure.H"
#include "adjustPhi.H"
#include "syncTools.H"
#include "choice.H"

bool Foam::fluidPhase::present(const fvMesh& mesh)
{
    // Absolute (the root case's constant, also for a decomposed case):
    // constant() alone is relative to the working directory, not the case
    // (mpmFoam -case <dir> run from elsewhere read a coupled case as pure MPM)
    const fileName tp(mesh.time().globalPath()/mesh.time().constant()/"transportProperties");
    if (!isFile(tp)) return false;

    // A fluid case must be complete: say what is missing, before reading.
    for (const word& f : {word("U"), word("p")})
    {
        if (!isFile(mesh.time().timePath()/f))
        {
            const IOdictionary dict
            (
                IOobject("transportProperties", mesh.time().constant(), mesh,
                    IOobject::MUST_READ, IOobject::NO_WRITE, false)
            );
            FatalIOErrorInFunction(dict)
                << "The case has a fluid (" << tp << ") but no field " << f
                << " at time " << mesh.time().timeName() << nl
                << "A fluid case needs " << mesh.time().timeName()
                << "/U and " << mesh.time().timeName() << "/p; remove "
                << "constant/transportProperties for a pure MPM case."
                << exit(FatalIOError);
        }
    }
    return true;
}

Foam::fluidPhase::fluidPhase(fvMesh& mesh, const pimpleControl& pimple)
:
    mesh_(mesh),
    reconstruct_(mesh),
    U_
    (
        IOobject("U", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    p_
    (
        IOobject("p", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    phi_
    (
        IOobject("phi", mesh.time().timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        fvc::flux(U_)
    ),
    alpha_
    (
        IOobject("alpha.fluid", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh,
        dimensionedScalar("one", dimless, 1),
        zeroGradientFvPatchScalarField::typeName
    ),
    alphaPhi_
    (
        IOobject("alphaPhi", mesh.time().timeName(), mesh),
        fvc::interpolate(alpha_)*phi_
    ),
    beta_
    (
        IOobject("beta", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh,
        dimensionedScalar(dimDensity/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    Us_
    (
        IOobject("Us.drag", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    alphaPhiSolid_
    (
        IOobject("alphaPhi.solid", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimVolume/dimTime, Zero)
    ),
    transport_(U_, phi_),
    rho_("rho", dimDensity, transport_)
{
    // Checked here, before the first solve: a non-positive density or
    // viscosity makes the momentum matrix lose its diagonal dominance and
    // the run ends in a floating-point exception (the traps stay on for the
    // fluid). Non-Newtonian models: their smallest viscosity.
    checkInRange(transport_, "rho", rho_.value(), numberRange{0, GREAT, false});
    checkInRange
    (
        transport_, "nu", gMin(transport_.nu()().primitiveField()),
        numberRange{0, GREAT, false}, " (kinematic viscosity [m^2/s])"
    );
    alpha_.oldTime();   // keep the old fluid fraction for d(alphaF)/dt
    turbulence_ = turbulenceModel::New(alpha_, U_, alphaPhi_, phi_, transport_);
    setRefCell(p_, pimple.dict(), pRefCell_, pRefValue_);
    mesh.setFluxRequired(p_.name());
    Info<< "Fluid: rho " << rho_.value() << ", nu " << average(transport_.nu()).value()
        << " (constant/transportProperties)" << nl << endl;
}

void Foam::fluidPhase::solve(pimpleControl& pimple, const dimensionedVector& g)
{
    volVectorField& U = U_;
    volScalarField& p = p_;
    const volScalarField& alpha = alpha_;
    const surfaceScalarField alphaf(fvc::interpolate(alpha));
    alphaPhi_ = alphaf*phi_;
    const volScalarField betaByRho(beta_/rho_);
    // g.x on the cells and the boundary faces (kinematic: [m2/s2])
    volScalarField gx
    (
        IOobject("gx", mesh_.time().timeName(), mesh_),
        g & mesh_.C()
    );

    while (pimple.loop())
    {
        fvVectorMatrix UEqn
        (
            fvm::ddt(alpha, U) + fvm::div(alphaPhi_, U)
          - fvm::Sp(fvc::ddt(alpha) + fvc::div(alphaPhi_), U)
          + turbulence_->divDevRhoReff(U)
          + fvm::Sp(betaByRho, U)
        );
        if (virtualMassReaction_)
        {
            // Cvm aS (dU/dt + (U.grad)U - dUs/dt): the time derivative
            // implicit (it adds to the fluid's inertia, as in
            // twoPhaseEulerFoam), the convective part from the last iterate
            const volScalarField::Internal CvmAlphaS(Cvm_*alphaSVm_());
            UEqn += CvmAlphaS*fvm::ddt(U);
            UEqn += CvmAlphaS*((U & fvc::grad(U))().internalField() - dUsdt_());
        }
        UEqn.relax();

        const volScalarField rAU(1.0/UEqn.A());
        const surfaceScalarField rAUf("Dp", fvc::interpolate(rAU));

        // Gravity and the explicit drag on faces, like the pressure gradient.
        // Gravity as the face gradient of g.x by the pressure's own snGrad:
        // the hydrostatic pressure then balances it on every face of any
        // mesh (g & Sf did not where the cells are skewed: 2.4 cm/s of
        // currents in still water at the refinement edge of a snapped mesh)
        const surfaceScalarField phiForces
        (
            rAUf*alphaf*fvc::snGrad(gx)*mesh_.magSf()
          + fvc::flux(rAU*betaByRho*Us_)
        );

        if (pimple.momentumPredictor())
        {
            Foam::solve
            (
                UEqn
             ==
                reconstruct_
                (
                    phiForces/rAUf - alphaf*fvc::snGrad(p)*mesh_.magSf()
                )
            );
        }

        while (pimple.correct())
        {
            volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U, p));
            surfaceScalarField phiHbyA
            (
                "phiHbyA",
                fvc::flux(HbyA) + alphaf*rAUf*fvc::ddtCorr(U, phi_)
            );
            if (p.needReference())
            {
                adjustPhi(phiHbyA, U, p);
            }
            phiHbyA += phiForces;

            // Model A: the flux correction is -aF_f rAU_f grad p
            const surfaceScalarField Dp("Dp", alphaf*rAUf);
            constrainPressure(p, U, phiHbyA, Dp);

            while (pimple.correctNonOrthogonal())
            {
                fvScalarMatrix pEqn
                (
                    fvm::laplacian(alphaf*Dp, p)
                 ==
                    fvc::div(alphaf*phiHbyA) + fvc::div(alphaPhiSolid_)
                );
                pEqn.setReference(pRefCell_, pRefValue_);
                pEqn.solve(mesh_.solver(p.select(pimple.finalInnerIter())));

                if (pimple.finalNonOrthogonalIter())
                {
                    phi_ = phiHbyA - pEqn.flux()/alphaf;
                    p.relax();
                    U = HbyA + rAU*reconstruct_((phiForces - pEqn.flux()/alphaf)/rAUf);
                    U.correctBoundaryConditions();
                }
            }
            alphaPhi_ = alphaf*phi_;
        }

        if (pimple.turbCorr())
        {
            transport_.correct();
            turbulence_->correct();
        }
    }

    if (DUDt_.valid())
    {
        // For the grains' virtual mass over the next step
        DUDt_() = fvc::ddt(U) + (U & fvc::grad(U));
    }
}

void Foam::fluidPhase::enableVirtualMass(scalar Cvm, bool reaction)
{
    Cvm_ = Cvm;
    virtualMassReaction_ = reaction;
    DUDt_.reset
    (
        new volVectorField
        (
            IOobject("DUDt", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedVector(dimAcceleration, Zero)
        )
    );
    if (reaction)
    {
        alphaSVm_.reset
        (
            new volScalarField::Internal
            (
                IOobject("alphaS.virtualMass", mesh_.time().timeName(), mesh_),
                mesh_,
                dimensionedScalar(dimless, Zero)
            )
        );
        dUsdt_.reset
        (
            new volVectorField::Internal
            (
                IOobject("dUsdt", mesh_.time().timeName(), mesh_),
                mesh_,
                dimensionedVector(dimAcceleration, Zero)
            )
        );
    }
    Info<< "    virtual mass: Cvm " << Cvm
        << (reaction ? ", the fluid feels the reaction" : ", on the grains only")
        << nl;
}

void Foam::fluidPhase::setVirtualMassFraction(const volScalarField::Internal& alphaS)
{
    alphaSVm_() = alphaS;
}

void Foam::fluidPhase::setSolid(const volVectorField& Us, const boolList& capped)
{
    if (dUsdt_.valid())
    {
        // The grains' acceleration from the sub-cycle averages of two
        // consecutive steps; zero at the first step (also after a restart)
        if (UsSet_) dUsdt_() = (Us.internalField() - Us_.internalField())/mesh_.time().deltaT();
        else dUsdt_() = dimensionedVector(dimAcceleration, Zero);
    }
    UsSet_ = true;
    Us_ = Us;
    alphaPhiSolid_ = fvc::interpolate(1 - alpha_)*fvc::flux(Us_);
    // Consistent with the cap: the solid flux into a capped cell is zero,
    // as its fluid fraction cannot fall further (a sediment of overlapping
    // stress-free grains would otherwise drive fluid out of it).
    // Grains never cross the domain boundary (every non-coupled patch is an
    // MPM wall): no solid flux there, which also keeps the pressure
    // equation of a closed box compatible. Processor and cyclic patches
    // are not walls: they take the interior rule, with the neighbour
    // cell's cap from the other side.
    boolList nbrCapped;
    syncTools::swapBoundaryCellList(mesh_, capped, nbrCapped);
    const label nInternal = mesh_.nInternalFaces();
    for (auto& pf : alphaPhiSolid_.boundaryFieldRef())
    {
        const polyPatch& pp = pf.patch().patch();
        if (!pp.coupled()) { pf = 0; continue; }
        const labelUList& fc = pp.faceCells();
        forAll(pf, i)
        {
            if ((pf[i] > 0 && nbrCapped[pp.start() + i - nInternal]) || (pf[i] < 0 && capped[fc[i]]))
            {
                pf[i] = 0;
            }
        }
    }
    scalarField& f = alphaPhiSolid_.primitiveFieldRef();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    forAll(f, facei)
    {
        if ((f[facei] > 0 && capped[nei[facei]]) || (f[facei] < 0 && capped[own[facei]]))
        {
            f[facei] = 0;
        }
    }
}

Foam::scalar Foam::fluidPhase::courantNumber(scalar dt) const
{
    const scalarField sumPhi(fvc::surfaceSum(mag(phi_))().primitiveField());
    return 0.5*gMax(sumPhi/mesh_.V().field())*dt;
}

Foam::scalar Foam::fluidPhase::continuityError() const
{
    const volScalarField err(fvc::div(alphaPhi_ + alphaPhiSolid_));
    return mesh_.time().deltaTValue()*gSum(mag(err.primitiveField())*mesh_.V())/gSum(mesh_.V());
}

Foam::scalar Foam::fluidPhase::alphaTransportError() const
{
    const volScalarField err(fvc::ddt(alpha_) + fvc::div(alphaPhi_));
    return mesh_.time().deltaTValue()*gSum(mag(err.primitiveField())*mesh_.V())/gSum(mesh_.V());
}
