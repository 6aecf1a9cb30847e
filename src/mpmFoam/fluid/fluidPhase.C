#include "fluidPhase.H"
#include "singleFluid.H"
#include "vofFluid.H"
#include "syncTools.H"
#include "choice.H"

const char* Foam::fluidPhase::modelName(model m)
{
    switch (m)
    {
        case model::single: return "single";
        case model::VOF: return "VOF";
    }
    return "?";
}

bool Foam::fluidPhase::parseModel(const std::string& s, model& m)
{
    for (const model c : {model::single, model::VOF})
    {
        if (s == modelName(c)) { m = c; return true; }
    }
    return false;
}

namespace
{
    // constant/transportProperties, not registered (the models register
    // their own copy)
    Foam::IOdictionary transportDict(const Foam::fvMesh& mesh)
    {
        using namespace Foam;
        return IOdictionary
        (
            IOobject("transportProperties", mesh.time().constant(), mesh,
                IOobject::MUST_READ, IOobject::NO_WRITE, false)
        );
    }
}

Foam::fluidPhase::model Foam::fluidPhase::selected(const fvMesh& mesh, bool echo)
{
    return readChoice(transportDict(mesh), "fluidModel", parseModel, modelName, "single VOF", model::single, echo);
}

bool Foam::fluidPhase::present(const fvMesh& mesh)
{
    // Absolute (the root case's constant, also for a decomposed case):
    // constant() alone is relative to the working directory, not the case
    // (mpmFoam -case <dir> run from elsewhere read a coupled case as pure MPM)
    const fileName tp(mesh.time().globalPath()/mesh.time().constant()/"transportProperties");
    if (!isFile(tp)) return false;

    // A fluid case must be complete: say what is missing, before reading.
    const model m = selected(mesh, false);
    if (m == model::VOF)
    {
        vofFluid::checkInput(mesh);
        return true;
    }
    for (const word& f : {word("U"), word("p")})
    {
        if (!isFile(mesh.time().timePath()/f))
        {
            FatalIOErrorInFunction(transportDict(mesh))
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

Foam::autoPtr<Foam::fluidPhase> Foam::fluidPhase::New(fvMesh& mesh, const pimpleControl& pimple)
{
    Info<< "Fluid (constant/transportProperties):" << nl;
    const model m = selected(mesh, true);
    if (m == model::VOF) return autoPtr<fluidPhase>(new vofFluid(mesh, pimple));
    return autoPtr<fluidPhase>(new singleFluid(mesh, pimple));
}

Foam::fluidPhase::fluidPhase(fvMesh& mesh)
:
    mesh_(mesh),
    reconstruct_(mesh),
    U_
    (
        IOobject("U", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
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
    )
{
    alpha_.oldTime();   // keep the old fluid fraction for d(alphaF)/dt
}

void Foam::fluidPhase::updateDUDt()
{
    if (DUDt_.valid())
    {
        // For the grains' virtual mass over the next step
        DUDt_() = fvc::ddt(U_) + (U_ & fvc::grad(U_));
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
