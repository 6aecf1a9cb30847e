#include "singleFluid.H"
#include "constrainHbyA.H"
#include "constrainPressure.H"
#include "adjustPhi.H"
#include "choice.H"

Foam::singleFluid::singleFluid(fvMesh& mesh, const pimpleControl& pimple)
:
    fluidPhase(mesh),
    p_
    (
        IOobject("p", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    transport_(U_, phi_),
    rho_("rho", dimDensity, transport_),
    rhoField_
    (
        IOobject("rho", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE, false),
        mesh,
        rho_
    )
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
    turbulence_ = turbulenceModel::New(alpha_, U_, alphaPhi_, phi_, transport_);
    setRefCell(p_, pimple.dict(), pRefCell_, pRefValue_);
    mesh.setFluxRequired(p_.name());
    Info<< "Fluid: rho " << rho_.value() << ", nu " << average(transport_.nu()).value()
        << " (constant/transportProperties)" << nl << endl;
}

void Foam::singleFluid::solve(pimpleControl& pimple, const dimensionedVector& g)
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

    updateDUDt();
}
