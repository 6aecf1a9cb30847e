#include "vofFluid.H"
#include "constrainHbyA.H"
#include "constrainPressure.H"
#include "adjustPhi.H"
#include "CMULES.H"
#include "EulerDdtScheme.H"
#include "gaussConvectionScheme.H"
#include "upwind.H"
#include "subCycle.H"
#include "uniformDimensionedFields.H"
#include "choice.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"

namespace
{
    const char* continuityName(Foam::vofFluid::alphaContinuity c)
    {
        using ac = Foam::vofFluid::alphaContinuity;
        return c == ac::bounded ? "bounded" : c == ac::conservative ? "conservative" : "corrected";
    }

    bool parseContinuity(const std::string& s, Foam::vofFluid::alphaContinuity& c)
    {
        using ac = Foam::vofFluid::alphaContinuity;
        for (const auto v : {ac::corrected, ac::conservative, ac::bounded})
        {
            if (s == continuityName(v)) { c = v; return true; }
        }
        return false;
    }

    Foam::IOdictionary readDict(const Foam::fvMesh& mesh, const Foam::word& name, const Foam::fileName& dir)
    {
        using namespace Foam;
        return IOdictionary
        (
            IOobject(name, dir, mesh, IOobject::MUST_READ, IOobject::NO_WRITE, false)
        );
    }
}

void Foam::vofFluid::checkInput(const fvMesh& mesh)
{
    const Time& runTime = mesh.time();
    const IOdictionary dict(readDict(mesh, "transportProperties", runTime.constant()));
    const char* example =
        "A VOF case's constant/transportProperties holds\n"
        "    fluidModel VOF;\n"
        "    phases     (water air);\n"
        "    water      { transportModel Newtonian; nu 1e-06; rho 1000; }\n"
        "    air        { transportModel Newtonian; nu 1.48e-05; rho 1; }\n"
        "    sigma      0.07;   // surface tension [N/m], 0 for none\n"
        "(etc/caseDicts/coupled/transportProperties.VOF)";

    // The two fluids and their properties
    if (!dict.found("phases", keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "fluidModel VOF needs the two fluids: no 'phases' in "
            << dict.name() << nl << example << exit(FatalIOError);
    }
    const wordList phases(dict.get<wordList>("phases"));
    if (phases.size() != 2 || phases[0] == phases[1])
    {
        FatalIOErrorInFunction(dict)
            << "fluidModel VOF needs two different fluids in 'phases', "
            << "the first the one of alpha." << (phases.size() ? phases[0] : word("water"))
            << "; got (" << spaceSeparated(phases).c_str() << ")" << nl << example
            << exit(FatalIOError);
    }
    for (const word& phase : phases)
    {
        if (!dict.isDict(phase))
        {
            FatalIOErrorInFunction(dict)
                << "fluidModel VOF: no properties of the fluid '" << phase
                << "' (a dictionary " << phase << " { transportModel; nu; rho; })"
                << " in " << dict.name() << "; both fluids of phases ("
                << spaceSeparated(phases).c_str() << ") need theirs" << nl
                << example << exit(FatalIOError);
        }
        const dictionary& pd = dict.subDict(phase);
        for (const word& k : {word("transportModel"), word("rho")})
        {
            if (!pd.found(k))
            {
                FatalIOErrorInFunction(pd)
                    << "fluidModel VOF: the fluid '" << phase << "' has no "
                    << k << "; both fluids of phases (" << spaceSeparated(phases).c_str() << ") need "
                    << "transportModel, its viscosity (nu for Newtonian) and rho"
                    << nl << example << exit(FatalIOError);
            }
        }
        // The density, as the mixture reads it (with or without dimensions)
        const dimensionedScalar rho("rho", dimDensity, pd);
        checkInRange(pd, "rho", rho.value(), numberRange{0, GREAT, false}, " (density [kg/m^3])");
    }

    // Surface tension: required as in interFoam, 0 for none; a constant
    // with dimensions must have those of a force per length
    if (!dict.found("sigma", keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "fluidModel VOF needs the surface tension 'sigma' [N/m] in "
            << dict.name() << " (sigma 0; for none)" << nl << example
            << exit(FatalIOError);
    }
    if (!dict.isDict("sigma"))
    {
        ITstream& is = dict.lookup("sigma");
        token t(is);
        if (t.isPunctuation() && t.pToken() == token::BEGIN_SQR)
        {
            is.putBack(t);
            const dimensionSet dims(is);
            const dimensionSet wanted(dimForce/dimLength);
            if (dims != wanted)
            {
                FatalIOErrorInFunction(dict)
                    << "The surface tension sigma has dimensions " << dims
                    << "; a surface tension is a force per length, [N/m] = "
                    << wanted << " (kg s^-2): e.g. sigma [1 0 -2 0 0 0 0] 0.07;"
                    << " or sigma 0.07;" << exit(FatalIOError);
            }
        }
        const dimensionedScalar sigma("sigma", dimForce/dimLength, dict);
        checkInRange(dict, "sigma", sigma.value(), numberRange{0, GREAT}, " (surface tension [N/m])");
    }

    // The fields, with what to do
    const word alpha1Name(IOobject::groupName("alpha", phases[0]));
    for (const word& f : {word("U"), word("p_rgh"), alpha1Name})
    {
        if (!isFile(runTime.timePath()/f))
        {
            FatalIOErrorInFunction(dict)
                << "fluidModel VOF: no field " << f << " at time "
                << runTime.timeName() << nl << "A VOF case needs "
                << runTime.timeName() << "/U, " << runTime.timeName()
                << "/p_rgh and " << runTime.timeName() << "/" << alpha1Name
                << " (the volume fraction of " << phases[0] << " in the fluid, "
                << "e.g. from a uniform 0 with setFields)" << exit(FatalIOError);
        }
    }

    // Laminar only, for now
    const fileName tp(runTime.globalPath()/runTime.constant()/"turbulenceProperties");
    if (isFile(tp))
    {
        const IOdictionary turb(readDict(mesh, "turbulenceProperties", runTime.constant()));
        const word type(turb.getOrDefault<word>("simulationType", "laminar"));
        const dictionary& lam = turb.optionalSubDict("laminar");
        const word lamModel(lam.getOrDefault<word>("laminarModel", "Stokes"));
        if (type != "laminar" || lamModel != "Stokes")
        {
            FatalIOErrorInFunction(turb)
                << "fluidModel VOF is laminar (Stokes) for now: "
                << "simulationType " << type << ", laminarModel " << lamModel
                << " are not available with it" << exit(FatalIOError);
        }
    }

    // The time derivative: Euler (as interFoam's alpha equation, without
    // its Crank-Nicolson option)
    for (const word& term : {word("ddt(alpha)"), word("ddt(alphaRho,U)")})
    {
        const ITstream& is = mesh.ddtScheme(term);
        const word scheme(is.size() && is[0].isWord() ? is[0].wordToken() : word());
        if (scheme != "Euler")
        {
            FatalIOErrorInFunction(mesh.schemesDict())
                << "fluidModel VOF takes the Euler time derivative; "
                << term << " is " << mesh.ddtScheme(term) << exit(FatalIOError);
        }
    }
}

Foam::vofFluid::vofFluid(fvMesh& mesh, const pimpleControl& pimple)
:
    fluidPhase(mesh),
    p_rgh_
    (
        IOobject("p_rgh", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    mixture_(U_, phi_),
    alpha1_(mixture_.alpha1()),
    alpha2_(mixture_.alpha2()),
    rho_
    (
        IOobject("rho", mesh.time().timeName(), mesh, IOobject::READ_IF_PRESENT),
        alpha1_*mixture_.rho1() + alpha2_*mixture_.rho2()
    ),
    rhoPhi_
    (
        IOobject("rhoPhi", mesh.time().timeName(), mesh),
        fvc::interpolate(rho_)*phi_
    ),
    alphaPhi10_
    (
        IOobject
        (
            IOobject::groupName("alphaPhi0", alpha1_.group()),
            mesh.time().timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE
        ),
        phi_*fvc::interpolate(alpha1_)
    ),
    hRef_("hRef", dimLength, Zero),
    gh_
    (
        IOobject("gh", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimAcceleration*dimLength, Zero)
    ),
    ghf_
    (
        IOobject("ghf", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimAcceleration*dimLength, Zero)
    ),
    p_
    (
        IOobject("p", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
        p_rgh_ + rho_*gh_
    )
{
    {
        IOobject h
        (
            IOobject::groupName("alphaPhi0", alpha1_.group()),
            mesh.time().timeName(), mesh, IOobject::READ_IF_PRESENT
        );
        alphaRestart_ = h.typeHeaderOk<surfaceScalarField>(true);
    }
    rho_.oldTime();
    // hRef as interFoam (constant/hRef, optional)
    const uniformDimensionedScalarField hRef
    (
        IOobject("hRef", mesh.time().constant(), mesh, IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false),
        dimensionedScalar("hRef", dimLength, Zero)
    );
    hRef_ = dimensionedScalar("hRef", dimLength, hRef.value());

    checkInRange
    (
        mixture_, "nu", min(gMin(mixture_.nuModel1().nu()().primitiveField()), gMin(mixture_.nuModel2().nu()().primitiveField())),
        numberRange{0, GREAT, false}, " (kinematic viscosity [m^2/s] of either fluid)"
    );
    setRefCell(p_, p_rgh_, pimple.dict(), pRefCell_, pRefValue_);
    mesh.setFluxRequired(p_rgh_.name());
    mesh.setFluxRequired(alpha1_.name());

    const dictionary& ac = mesh.solverDict(alpha1_.name());
    continuity_ = readChoice(ac, "alphaContinuity", parseContinuity, continuityName, "corrected conservative bounded", alphaContinuity::corrected);
    Info<< "    VOF: " << alpha1_.name() << " in (" << mixture_.phase1Name() << " "
        << mixture_.phase2Name() << "), rho " << mixture_.rho1().value() << " "
        << mixture_.rho2().value() << ", nu "
        << average(mixture_.nuModel1().nu()).value() << " "
        << average(mixture_.nuModel2().nu()).value() << ", sigma ";
    const dictionary& tp = mixture_;
    if (tp.isDict("sigma")) Info<< "(a model: " << tp.subDict("sigma").dictName() << ")";
    else Info<< dimensionedScalar("sigma", dimForce/dimLength, tp).value() << " N/m";
    Info<< nl
        << "    MULES: nAlphaCorr " << ac.get<label>("nAlphaCorr")
        << ", nAlphaSubCycles " << ac.get<label>("nAlphaSubCycles")
        << ", cAlpha " << mixture_.cAlpha()
        << ", MULESCorr " << Switch(ac.getOrDefault<bool>("MULESCorr", false))
        << ", alphaContinuity " << continuityName(continuity_)
        << " (fvSolution solvers " << alpha1_.name() << ")" << nl;
    if (continuity_ == alphaContinuity::corrected)
    {
        mesh.setFluxRequired("pcorr");
        Info<< "    alpha flux correction (where the grains change alpha.fluid): pcorr solved with "
            << (pcorrFromPRgh() ? "p_rgh's final solver, relTol 0 (no 'pcorr' in fvSolution solvers)"
                                : "fvSolution solvers 'pcorr'") << nl;
    }
    Info
        << (alphaRestart_ ? "    restarting alpha from the MULES flux\n" : "") << endl;
}

void Foam::vofFluid::setGravity(const dimensionedVector& g)
{
    // As interFoam's gh.H and createFields.H
    const dimensionedScalar ghRef
    (
        mag(g.value()) > SMALL
      ? g & (cmptMag(g.value())/mag(g.value()))*hRef_
      : dimensionedScalar("ghRef", g.dimensions()*dimLength, 0)
    );
    gh_ = (g & mesh_.C()) - ghRef;
    ghf_ = (g & mesh_.Cf()) - ghRef;
    p_ == p_rgh_ + rho_*gh_;
    if (p_rgh_.needReference())
    {
        p_ += dimensionedScalar("p", p_.dimensions(), pRefValue_ - getRefCellValue(p_, pRefCell_));
        p_rgh_ = p_ - rho_*gh_;
    }
}

void Foam::vofFluid::enableVirtualMass(scalar, bool)
{
    FatalErrorInFunction
        << "The virtualMass force is not available with fluidModel VOF yet "
        << "(the grains' added mass takes one fluid density): remove it "
        << "from coupling forces" << exit(FatalError);
}

Foam::scalar Foam::vofFluid::waterVolume(bool old) const
{
    const scalarField& a1 = old ? alpha1_.oldTime().primitiveField() : alpha1_.primitiveField();
    const scalarField& aF = old ? alpha_.oldTime().primitiveField() : alpha_.primitiveField();
    return gSum(a1*aF*mesh_.V().field());
}

Foam::scalar Foam::vofFluid::interfaceCourantNumber(scalar dt) const
{
    // interFoam's alphaCourantNo.H
    const scalarField sumPhi
    (
        mixture_.nearInterface()().primitiveField()*fvc::surfaceSum(mag(phi_))().primitiveField()
    );
    return 0.5*gMax(sumPhi/mesh_.V().field())*dt;
}

void Foam::vofFluid::report(Ostream& os) const
{
    const scalar w = waterVolume(false);
    const scalar w0 = max(water0_, VSMALL);
    os  << "VOF: water volume int alpha1 alpha.fluid dV " << w
        << ", relative to the start " << (w - water0_)/w0
        << ", out through the boundary " << waterOut_/w0
        << ", balance (V - V0 + out)/V0 " << (w - water0_ + waterOut_)/w0
        << "; " << alpha1_.name() << " in [" << gMin(alpha1_.primitiveField())
        << ", " << gMax(alpha1_.primitiveField()) << "]" << nl;
}

void Foam::vofFluid::alphaEqn
(
    const volScalarField& alphacOld,
    const volScalarField& alphacNew,
    const surfaceScalarField& alphaPhic
)
{
    const fvMesh& mesh = mesh_;
    volScalarField& alpha1 = alpha1_;
    volScalarField& alpha2 = alpha2_;
    const dictionary& alphaControls = mesh.solverDict(alpha1.name());
    const label nAlphaCorr(alphaControls.get<label>("nAlphaCorr"));
    const bool MULESCorr(alphaControls.getOrDefault("MULESCorr", false));
    const bool alphaApplyPrevCorr(alphaControls.getOrDefault("alphaApplyPrevCorr", false));
    const scalar icAlpha(alphaControls.getOrDefault<scalar>("icAlpha", 0));
    const scalar scAlpha(alphaControls.getOrDefault<scalar>("scAlpha", 0));
    const word alphaScheme("div(phi,alpha)");
    const word alpharScheme("div(phirb,alpha)");

    // aF over this (sub-)step: its old value in the time derivative
    volScalarField alphac
    (
        IOobject("alphac", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE, false),
        alphacNew
    );
    alphac.oldTime().primitiveFieldRef() = alphacOld.primitiveField();

    // The fluid's own continuity residual R = d(aF)/dt + div(aF_f phi): the
    // projected aF does not follow the fluid's flux exactly (the log's
    // "alpha transport error"). bounded: alpha1 takes it with it, as in
    // MPPICInterFoam's predictor, d(aF alpha1)/dt + div(aF_f phi alpha1) =
    // alpha1 R: a uniform alpha1 stays uniform and bounded, the water volume
    // changes by int alpha1 R (zero where alpha1 is uniform over R's cells:
    // R sums to the fluid volume's change, zero, the grains being
    // incompressible). conservative: no source, the water volume is kept
    // and alpha1 drifts off its bounds where R is not zero. With aF = 1, R
    // is div(phi), the pressure solver's tolerance.
    const volScalarField::Internal Sp
    (
        IOobject("alphaSp", mesh.time().timeName(), mesh),
        (continuity_ == alphaContinuity::bounded ? scalar(1) : scalar(0))
       *(fvc::ddt(alphac) + fvc::div(alphaPhic))().internalField()
    );
    zeroField Su;

    // Euler only (checkInput): cnCoeff 1
    surfaceScalarField phic(mixture_.cAlpha()*mag(alphaPhic/mesh.magSf()));
    if (icAlpha > 0)
    {
        phic *= (1.0 - icAlpha);
        phic += (mixture_.cAlpha()*icAlpha)*fvc::interpolate(mag(U_));
    }
    if (scAlpha > 0)
    {
        phic += scAlpha*mag(mesh.delta() & fvc::interpolate(symm(fvc::grad(U_))));
    }
    // No compression at non-coupled boundary faces
    surfaceScalarField::Boundary& phicBf = phic.boundaryFieldRef();
    forAll(phic.boundaryField(), patchi)
    {
        if (!phicBf[patchi].coupled()) phicBf[patchi] == 0;
    }

    const surfaceScalarField& phiCN = alphaPhic;

    if (MULESCorr)
    {
        fvScalarMatrix alpha1Eqn
        (
            fv::EulerDdtScheme<scalar>(mesh).fvmDdt(alphac, alpha1)
          + fv::gaussConvectionScheme<scalar>
            (
                mesh,
                phiCN,
                upwind<scalar>(mesh, phiCN)
            ).fvmDiv(phiCN, alpha1)
         ==
            fvm::Sp(Sp, alpha1)
        );
        alpha1Eqn.solve();

        tmp<surfaceScalarField> talphaPhi1UD(alpha1Eqn.flux());
        alphaPhi10_ = talphaPhi1UD();

        if (alphaApplyPrevCorr && talphaPhi1Corr0_.valid())
        {
            MULES::correct(alphac, alpha1, alphaPhi10_, talphaPhi1Corr0_.ref(), oneField(), zeroField());
            alphaPhi10_ += talphaPhi1Corr0_();
        }
        // Cache the upwind-flux
        talphaPhi1Corr0_ = talphaPhi1UD;

        alpha2 = 1.0 - alpha1;
        mixture_.correct();
    }

    for (int aCorr=0; aCorr<nAlphaCorr; aCorr++)
    {
        surfaceScalarField phir(phic*mixture_.nHatf());

        tmp<surfaceScalarField> talphaPhi1Un
        (
            fvc::flux(phiCN, alpha1, alphaScheme)
          + fvc::flux(-fvc::flux(-phir, alpha2, alpharScheme), alpha1, alpharScheme)
        );

        if (MULESCorr)
        {
            tmp<surfaceScalarField> talphaPhi1Corr(talphaPhi1Un() - alphaPhi10_);
            volScalarField alpha10("alpha10", alpha1);

            MULES::correct
            (
                alphac,
                alpha1,
                talphaPhi1Un(),
                talphaPhi1Corr.ref(),
                Sp,
                (-Sp*alpha1)(),
                oneField(),
                zeroField()
            );

            // Under-relax the correction for all but the 1st corrector
            if (aCorr == 0)
            {
                alphaPhi10_ += talphaPhi1Corr();
            }
            else
            {
                alpha1 = 0.5*alpha1 + 0.5*alpha10;
                alphaPhi10_ += 0.5*talphaPhi1Corr();
            }
        }
        else
        {
            alphaPhi10_ = talphaPhi1Un;

            MULES::explicitSolve
            (
                alphac,
                alpha1,
                phiCN,
                alphaPhi10_,
                Sp,
                Su,
                oneField(),
                zeroField()
            );
        }

        alpha2 = 1.0 - alpha1;
        mixture_.correct();
    }

    if (alphaApplyPrevCorr && MULESCorr)
    {
        talphaPhi1Corr0_ = alphaPhi10_ - talphaPhi1Corr0_;
        talphaPhi1Corr0_.ref().rename("alphaPhi1Corr0");
    }
    else
    {
        talphaPhi1Corr0_.clear();
    }

    // Euler: rhoPhi = alphaPhi10 (rho1 - rho2) + phiCN rho2 (rhofs.H)
    const dimensionedScalar& rho1f(mixture_.rho1());
    const dimensionedScalar& rho2f(mixture_.rho2());
    rhoPhi_ = alphaPhi10_*(rho1f - rho2f) + phiCN*rho2f;

    // The water through the boundary over this (sub-)step
    scalar out = 0;
    forAll(alphaPhi10_.boundaryField(), patchi)
    {
        if (!alphaPhi10_.boundaryField()[patchi].coupled())
        {
            out += sum(alphaPhi10_.boundaryField()[patchi]);
        }
    }
    waterOut_ += returnReduce(out, sumOp<scalar>())*mesh.time().deltaTValue();
}

bool Foam::vofFluid::pcorrFromPRgh() const
{
    return !mesh_.solutionDict().subDict("solvers").found("pcorr");
}

void Foam::vofFluid::correctAlphaFlux()
{
    // The last pressure solve made aF_f phi satisfy the mixture's continuity
    // with the grains' face flux, over the last step. The alpha1 transport
    // needs it to carry this step's change of the projected aF instead:
    // div(aF_f phi) = -d(aF)/dt in every cell, or alpha1 = 1 stops being a
    // solution of its own equation (the residual R of alphaContinuity). As
    // interFoam's correctPhi for a moving mesh: phi -= the flux of pcorr,
    //     laplacian(aF_f/rho_f, pcorr) = div(aF_f phi) + d(aF)/dt,
    // pcorr fixed (0) where p_rgh is fixed, zero gradient elsewhere. The
    // weight 1/rho_f is the pressure equation's (its aF_f rAU_f, rAU ~
    // dt/rho): the fluid that makes room for the grains is the one that
    // would move, the air where there is air. With aF_f alone the air
    // displaced by a slide still above the surface reached the open top
    // partly through the water, which rose 0.06 mm at the first gauge of
    // tutorials/multiphase/granularSlideWave before the slide touched it.
    // Nothing to correct where aF did not change (no grains, or oneWay
    // still ones): the solve is skipped, so a case without moving grains
    // pays nothing. Not OpenFOAM's CorrectPhi itself: it needs 'pcorr'
    // and 'pcorrFinal' solver entries, which VOF cases written before this
    // correction do not have. One solve, without PIMPLE's non-orthogonal
    // correctors, is enough: the matrix's flux() carries the same explicit
    // non-orthogonal part as the matrix that was solved, so div of the
    // corrected flux balances d(aF)/dt to the solver's tolerance on any
    // mesh (the slide tutorial's 45-degree trapezoid: max |R| dt 3.0e-10
    // after one solve, 3.3e-8 after two correctors, 0.14 before).
    const scalar change = gMax(mag(alpha_.primitiveField() - alpha_.oldTime().primitiveField())());
    if (change == 0) return;

    wordList pcorrTypes(p_rgh_.boundaryField().size(), zeroGradientFvPatchScalarField::typeName);
    forAll(p_rgh_.boundaryField(), patchi)
    {
        if (p_rgh_.boundaryField()[patchi].fixesValue())
        {
            pcorrTypes[patchi] = fixedValueFvPatchScalarField::typeName;
        }
    }
    volScalarField pcorr
    (
        IOobject("pcorr", mesh_.time().timeName(), mesh_, IOobject::NO_READ, IOobject::NO_WRITE, false),
        mesh_,
        dimensionedScalar(dimDensity*dimArea/dimTime, Zero),
        pcorrTypes
    );
    const surfaceScalarField weight(fvc::interpolate(alpha_)/fvc::interpolate(rho_));
    fvScalarMatrix pcorrEqn
    (
        fvm::laplacian(weight, pcorr) == fvc::div(alphaPhi_) + fvc::ddt(alpha_)
    );
    if (pcorr.needReference()) pcorrEqn.setReference(0, 0);
    if (pcorrFromPRgh())
    {
        dictionary d(mesh_.solverDict(p_rgh_.select(true)));
        d.set("relTol", scalar(0));
        pcorrEqn.solve(d);
    }
    else
    {
        pcorrEqn.solve(mesh_.solverDict("pcorr"));
    }
    alphaPhi_ -= pcorrEqn.flux();
}

void Foam::vofFluid::solve(pimpleControl& pimple, const dimensionedVector&)
{
    volVectorField& U = U_;
    const surfaceScalarField alphaf(fvc::interpolate(alpha_));
    alphaPhi_ = alphaf*phi_;
    if (water0_ < 0) water0_ = waterVolume(true);

    while (pimple.loop())
    {
        if (continuity_ == alphaContinuity::corrected) correctAlphaFlux();

        // --- alpha1, sub-cycled as interFoam's alphaEqnSubCycle.H, with
        // aF moving linearly over the sub-cycles
        {
            const label nAlphaSubCycles(mesh_.solverDict(alpha1_.name()).get<label>("nAlphaSubCycles"));
            const volScalarField alphac0("alphac0", alpha_.oldTime());
            if (nAlphaSubCycles > 1)
            {
                const dimensionedScalar totalDeltaT = mesh_.time().deltaT();
                surfaceScalarField rhoPhiSum
                (
                    IOobject("rhoPhiSum", mesh_.time().timeName(), mesh_),
                    mesh_,
                    dimensionedScalar(rhoPhi_.dimensions(), Zero)
                );
                label k = 0;
                for
                (
                    subCycle<volScalarField> alphaSubCycle(alpha1_, nAlphaSubCycles);
                    !(++alphaSubCycle).end();
                )
                {
                    const scalar w0 = scalar(k)/nAlphaSubCycles;
                    const scalar w1 = scalar(k + 1)/nAlphaSubCycles;
                    ++k;
                    const volScalarField a0("a0", (1 - w0)*alphac0 + w0*alpha_);
                    const volScalarField a1("a1", (1 - w1)*alphac0 + w1*alpha_);
                    alphaEqn(a0, a1, alphaPhi_);
                    rhoPhiSum += (mesh_.time().deltaT()/totalDeltaT)*rhoPhi_;
                }
                rhoPhi_ = rhoPhiSum;
            }
            else
            {
                alphaEqn(alphac0, alpha_, alphaPhi_);
            }
            rho_ == alpha1_*mixture_.rho1() + alpha2_*mixture_.rho2();
        }
        mixture_.correct();

        // --- Momentum: aF rho; rhoPhi is the mass flux aF_f rho_f phi of
        // the alpha1 transport (MPPICInterFoam's)
        volScalarField alphaRho
        (
            IOobject("alphaRho", mesh_.time().timeName(), mesh_, IOobject::NO_READ, IOobject::NO_WRITE, false),
            alpha_*rho_
        );
        alphaRho.oldTime().primitiveFieldRef() = alpha_.oldTime().primitiveField()*rho_.oldTime().primitiveField();
        const volScalarField alphaRhoNuEff("alphaRhoNuEff", alphaRho*mixture_.nu());

        fvVectorMatrix UEqn
        (
            fvm::ddt(alphaRho, U) + fvm::div(rhoPhi_, U)
          - fvm::Sp(fvc::ddt(alphaRho) + fvc::div(rhoPhi_), U)
          + (
              - fvc::div(alphaRhoNuEff*dev2(T(fvc::grad(U))))
              - fvm::laplacian(alphaRhoNuEff, U)
            )
          + fvm::Sp(beta_, U)
        );
        UEqn.relax();

        const volScalarField rAU(1.0/UEqn.A());
        const surfaceScalarField rAUf("rAUf", fvc::interpolate(rAU));

        // Surface tension, gravity (p_rgh: the g.h grad rho part) and the
        // explicit drag on faces, as the pressure gradient
        const surfaceScalarField phig
        (
            alphaf*(mixture_.surfaceTensionForce() - ghf_*fvc::snGrad(rho_))*rAUf*mesh_.magSf()
          + fvc::flux(rAU*beta_*Us_)
        );

        if (pimple.momentumPredictor())
        {
            Foam::solve
            (
                UEqn
             ==
                reconstruct_(phig/rAUf - alphaf*fvc::snGrad(p_rgh_)*mesh_.magSf())
            );
        }

        while (pimple.correct())
        {
            volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U, p_rgh_));
            surfaceScalarField phiHbyA
            (
                "phiHbyA",
                fvc::flux(HbyA)
              + alphaf*fvc::interpolate(rho_*rAU)*fvc::ddtCorr(U, phi_)
            );
            if (p_rgh_.needReference())
            {
                adjustPhi(phiHbyA, U, p_rgh_);
            }
            phiHbyA += phig;

            // Model A: the flux correction is -aF_f rAU_f grad p_rgh
            const surfaceScalarField Dp("Dp", alphaf*rAUf);
            constrainPressure(p_rgh_, U, phiHbyA, Dp);

            while (pimple.correctNonOrthogonal())
            {
                fvScalarMatrix p_rghEqn
                (
                    fvm::laplacian(alphaf*Dp, p_rgh_)
                 ==
                    fvc::div(alphaf*phiHbyA) + fvc::div(alphaPhiSolid_)
                );
                p_rghEqn.setReference(pRefCell_, getRefCellValue(p_rgh_, pRefCell_));
                p_rghEqn.solve(mesh_.solver(p_rgh_.select(pimple.finalInnerIter())));

                if (pimple.finalNonOrthogonalIter())
                {
                    phi_ = phiHbyA - p_rghEqn.flux()/alphaf;
                    p_rgh_.relax();
                    U = HbyA + rAU*reconstruct_((phig - p_rghEqn.flux()/alphaf)/rAUf);
                    U.correctBoundaryConditions();
                }
            }
            alphaPhi_ = alphaf*phi_;

            p_ == p_rgh_ + rho_*gh_;
            if (p_rgh_.needReference())
            {
                p_ += dimensionedScalar("p", p_.dimensions(), pRefValue_ - getRefCellValue(p_, pRefCell_));
                p_rgh_ = p_ - rho_*gh_;
            }
        }
    }
    updateDUDt();
}
