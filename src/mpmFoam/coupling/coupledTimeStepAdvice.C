#include "coupledTimeStepAdvice.H"
#include "dragForce.H"
#include "stableCourant.H"
#include "clockTime.H"
#include "cpuTime.H"
#include "stability/coupledAdvice.hpp"

namespace
{

mpm::stability::CouplingMode analysedMode(Foam::fluidCoupling::couplingMode m)
{
    using M = Foam::fluidCoupling::couplingMode;
    using A = mpm::stability::CouplingMode;
    return m == M::oneWay ? A::oneWay : m == M::twoWayMomentum ? A::twoWayMomentum : A::twoWay;
}

} // namespace

void Foam::printCoupledTimeStepAdvice
(
    const fluidCoupling& coupling,
    const pimpleControl& pimple,
    scalar fluidDeltaT
)
{
    namespace st = mpm::stability;
    const mpmModel& mpm = coupling.mpm();
    const materialLibrary& materials = mpm.materials();

    // The first material with a drag
    const dragForce* drag = dynamic_cast<const dragForce*>(coupling.findForce("drag"));
    label material = -1;
    for (label i = 0; drag && i < materials.size() && material < 0; ++i)
    {
        if (drag->law(i)) material = i;
    }
    if (material < 0)
    {
        Info<< "Coupled time-step advice: none (no drag in the coupling forces "
            << "or no material with a drag)" << nl << endl;
        return;
    }
    scalar alphaS = 0;
    forAll(coupling.mesh().C(), celli)
    {
        alphaS = max(alphaS, coupling.cappedAlphaSolid(celli));
    }
    reduce(alphaS, maxOp<scalar>());
    if (!(alphaS > 0 && alphaS < 1))
    {
        Info<< "Coupled time-step advice: none (largest alpha.solid " << alphaS
            << " at the start is not in (0, 1))" << nl << endl;
        return;
    }
    const volScalarField nu(coupling.fluid().mu()/coupling.fluid().rho());

    st::CoupledCase c;
    c.base.solid = analysedStep(mpm.controls().step);
    c.base.solid.offsets = {0.5};
    c.base.mode = analysedMode(coupling.mode());
    c.base.pressureGradient = coupling.findForce("pressureGradient") != nullptr;
    c.base.pisoCorrectors = pimple.nCorrPISO();
    c.base.alphaS = alphaS;
    c.lawName = materials.model(material);
    c.dragName = mpm.dict().subDict("materials").subDict(materials.names()[material])
        .subDict("drag").get<word>("model");
    // The densest fluid (the VOF mixture's water): the stiffest drag
    c.rhoF = gMax(coupling.fluid().rho().primitiveField());
    c.nuF = gMax(nu.primitiveField());
    c.h = mpm.system().lattice().h;
    c.dt = fluidDeltaT;
    c.courant = mpm.controls().courant;

    // Every rank has the same inputs: the master alone analyses
    const clockTime timer;
    cpuTime cpu;
    if (Pstream::master())
    {
        const auto law = materials.create(material);
        const st::CoupledAdvice advice = st::adviseCoupled(c, *law, *drag->law(material));
        for (const std::string& line : st::adviceLines(c, advice))
        {
            Info<< line.c_str() << nl;
        }
    }
    // As for the pure-MPM check (stableCourant.H): the analysis has lumped
    // mass and PIC/FLIP transfer only
    const mpm::StepOptions& o = mpm.controls().step;
    if (o.transfer == mpm::Transfer::apic)
    {
        Info<< "  (the analysis takes lumped mass and PIC/FLIP transfer; this case's "
            << "APIC transfer is analysed as PIC, alpha 0: its point velocity is the "
            << "PIC interpolation, its affine term is not analysed)" << nl;
    }
    if (o.massMatrix == mpm::MassMatrix::consistent)
    {
        Info<< "  (the analysis takes lumped mass and PIC/FLIP transfer; this case's "
            << "consistent mass is not analysed)" << nl;
    }
    Info<< "  (material " << materials.names()[material] << ", alpha.solid "
        << alphaS << ": the largest at the start; the analysis took "
        << timer.elapsedTime() << " s, CPU " << cpu.elapsedCpuTime() << " s)"
        << nl << endl;
}
