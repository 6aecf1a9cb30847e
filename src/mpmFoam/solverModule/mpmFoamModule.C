#include "mpmFoamModule.H"
#include <sstream>
#include "addToRunTimeSelectionTable.H"
#include "clockTime.H"
#include "choice.H"
#include "mpmControls.H"
#include "completeTimes.H"
#include "accuracyFrontLog.H"
#include "coupledTimeStepAdvice.H"
#include "stableCourant.H"
#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(mpmFoamModule, 0);
    addToRunTimeSelectionTable(solverModule, mpmFoamModule, fvMesh);
}

Foam::mpmFoamModule::mpmFoamModule(fvMesh& mesh, bool adviseTimeStep)
:
    solverModule(mesh),
    mpm_(mesh)
{
    // The state at the start time; not when only advising: the report
    // writes the diagnostics' files (postProcessing/mpmSummary), and the
    // advice writes nothing
    if (!adviseTimeStep) mpm_.report(Info);

    if (fluidPhase::present(mesh))
    {
        pimple_.reset(new pimpleControl(mesh));
        fluid_ = fluidPhase::New(mesh, pimple_());
        coupling_.reset(new fluidCoupling(mesh, mpm_, fluid_()));
        fluid_->setGravity(coupling_->g());

        checkStep(runTime, "the fluid step; the grains sub-cycle within it");
        if (coupling_->timeStepAdvice() || adviseTimeStep)
        {
            printCoupledTimeStepAdvice(coupling_(), pimple_(), runTime.deltaTValue());
        }
        const dictionary& cd = runTime.controlDict();
        adjustFluidStep_ = cd.getOrDefault<bool>("adjustTimeStep", false);
        Info<< "Fluid time step: " << (adjustFluidStep_ ? "adjustable" : "fixed")
            << " (controlDict adjustTimeStep)" << nl;
        if (adjustFluidStep_)
        {
            maxCo_ = readBounded(cd, "maxCo", 1, SMALL, GREAT);
            maxFluidDeltaT_ = readBounded(cd, "maxDeltaT", GREAT, SMALL, GREAT);
            // VOF: the interface Courant number too, as interFoam's
            // setDeltaT.H (default: maxCo)
            if (fluid_->type() == fluidPhase::model::VOF)
            {
                maxAlphaCo_ = readBounded(cd, "maxAlphaCo", maxCo_, SMALL, GREAT);
            }
        }
        Info<< endl;
    }
    else if (adviseTimeStep)
    {
        // No coupled analysis without a fluid: the pure-MPM check instead
        const stableCourant l = analysedCourantLimit(mpm_.controls().step);
        const scalar courant = mpm_.controls().courant;
        Info<< "Time-step advice: this case has no fluid (no "
            << "constant/transportProperties); the coupled advice "
            << "(docs/stabilityAnalysis.md 7b.7) is for coupled cases" << nl
            << "  pure MPM: the solver checks its step against the stable "
            << "Courant number of the case's algorithm "
            << "(docs/stabilityAnalysis.md 6d): ";
        if (l.limit > 0)
        {
            Info<< l.limit << " (" << l.description.c_str() << "); timeStep "
                << "courant " << courant << ": margin " << l.limit/courant << nl;
        }
        else
        {
            Info<< "not analysed (" << l.description.c_str() << "); steps are "
                << "checked against Courant number 1" << nl;
        }
        Info<< endl;
    }
    wallClock_ = clockTime();   // the time loop starts here
}

void Foam::mpmFoamModule::printProgress() const
{
    const scalar t0 = runTime.startTime().value();
    const scalar t1 = runTime.endTime().value();
    const scalar done = min(max((runTime.value() - t0)/max(t1 - t0, VSMALL), 0), 1);
    const scalar wall = wallClock_.elapsedTime();
    // The time left from the recent rate, not from the whole run's: the
    // first progress interval carries the start-up (first touches, the P2G
    // loop's trials), and a run's rate drifts as its material spreads or
    // settles. The rate over the last quarter of the intervals (at least
    // one, never the first while others exist) gives the estimate; its
    // difference from the last interval's alone says how sure it is.
    progress_.emplace_back(wall, done);
    if (progress_.size() > 64) progress_.pop_front();
    const label n = label(progress_.size());
    auto rate = [&](label from)
    {
        const scalar dw = progress_.back().first - progress_[from].first;
        return dw > 0 ? (progress_.back().second - progress_[from].second)/dw : scalar(0);
    };
    scalar r = wall > 0 ? done/wall : 0;   // the first line: all there is
    std::ostringstream how;
    if (n < 2) how << "from the run so far";
    if (n >= 3)
    {
        const label from = max(label(1), n - 1 - max(label(1), (n - 1)/4));
        r = rate(from);
        const scalar last = rate(n - 2);
        how << "rate of the last " << std::round(10*(wall - progress_[from].first))/10
            << " s, +-" << std::round(r > 0 ? 100*mag(last - r)/r : 0) << " %";
    }
    else if (n == 2)
    {
        r = rate(0);
        how << "from one interval, rough";
    }
    Info<< "Progress: time " << runTime.timeName() << " of " << t1 << ", "
        << std::round(1000*done)/10 << " % done, wall time "
        << std::round(10*wall)/10 << " s, about "
        << std::round(r > 0 ? 10*(1 - done)/r : 0)/10 << " s left (" << how.str().c_str() << ")" << nl;
}

Foam::scalar Foam::mpmFoamModule::maxDeltaT() const
{
    if (!coupled()) return mpm_.deltaT();
    // Coupled: the solids sub-cycle within the fluid step, which is the
    // controlDict deltaT, or adjusted to maxCo as pimpleFoam's setDeltaT.H
    // does (growth at most 20 % a step, capped by maxDeltaT).
    if (!adjustFluidStep_) return VGREAT;
    const scalar dt = runTime.deltaTValue();
    scalar maxFact = maxCo_/(fluid_->courantNumber(dt) + SMALL);
    if (fluid_->type() == fluidPhase::model::VOF)
    {
        maxFact = min(maxFact, maxAlphaCo_/(fluid_->interfaceCourantNumber(dt) + SMALL));
    }
    const scalar fact = min(min(maxFact, 1 + 0.1*maxFact), 1.2);
    return min(fact*dt, maxFluidDeltaT_);
}

void Foam::mpmFoamModule::prePredictor()
{
    const scalar dt = runTime.deltaTValue();

    if (!coupled())
    {
        // The step header, every logInterval steps only
        logStep_ = mpm_.logThisStep();
        if (logStep_)
        {
            Info<< "Courant Number max: " << mpm_.courantNumber(dt)
                << " deltaT = " << dt << nl
                << "Time = " << runTime.timeName() << nl << endl;
        }
        return;
    }

    // Coupled: every logInterval fluid steps (and at write times) the
    // step's lines; the others are held back until postWrite
    logStep_ = fluidSteps_++ % mpm_.controls().logInterval == 0 || runTime.writeTime();
    if (!logStep_) held_.reset(new heldLog);

    // The solids first, over the whole fluid step (explicit coupling: the
    // fluid then sees their new fraction and velocity).
    // The fluid Courant number of this step, from the last flux.
    const scalar Co = fluid_->courantNumber(dt);
    Info<< "fluid: Courant Number max " << Co;
    if (fluid_->type() == fluidPhase::model::VOF)
    {
        Info<< ", interface Courant Number max " << fluid_->interfaceCourantNumber(dt);
    }
    Info<< " deltaT = " << dt << nl
        << "Time = " << runTime.timeName() << nl << endl;
    if (!adjustFluidStep_ && Co > 1 && !fluidCourantWarned_)
    {
        // Once per run: PIMPLE with one outer corrector is not reliable
        // above ~1, and the answer changes with the step.
        fluidCourantWarned_ = true;
        WarningInFunction
            << "The fluid step deltaT = " << dt << " gives Courant number "
            << Co << " > 1 at time " << runTime.timeName() << ": use deltaT "
            << "<= " << 0.5*dt/Co << " (Courant 0.5) in controlDict, or "
            << "adjustTimeStep yes; maxCo 0.5;" << endl;
    }

    coupling_->advanceSolids(dt);
    const label nSub = coupling_->lastSubCycles();
    Info<< "MPM: " << nSub << " sub-cycles of deltaT = " << dt/nSub
        << ", Courant Number max " << mpm_.courantNumber(dt/nSub) << nl;
}

void Foam::mpmFoamModule::momentumPredictor()
{
    // Pure MPM: the whole MPM step (P2G, nodal momentum, G2P, stresses)
    if (!coupled())
    {
        mpm_.evolve(runTime.deltaTValue());
    }
}

void Foam::mpmFoamModule::pressureCorrector()
{
    if (!coupled()) return;

    // The fluid's whole PIMPLE loop: fluidPhase::solve loops itself
    const clockTime timer;
    fluid_->solve(pimple_(), coupling_->g());
    fluidTime_ += timer.elapsedTime();
    Info<< "fluid: continuity error " << fluid_->continuityError()
        << ", min alpha.fluid " << gMin(fluid_->alpha().primitiveField())
        << ", alpha transport error " << fluid_->alphaTransportError() << nl;
    fluid_->report(Info);
}

void Foam::mpmFoamModule::postSolve()
{
    mpm_.write();   // points and lattice fields, at write times only
}

void Foam::mpmFoamModule::postWrite()
{
    // After runTime.write(): every field of this time is on disk
    if (runTime.writeTime()) markTimeComplete(runTime);

    if (coupled() || logStep_ || runTime.writeTime())
    {
        mpm_.report(Info);   // held back too: its summary file is per step
        printProgress();
        runTime.printExecutionTime(Info);
    }
    held_.reset();
}

void Foam::mpmFoamModule::end()
{
    List<Tuple2<word, scalar>> effects;
    if (coupled())
    {
        effects.append(Tuple2<word, scalar>("fluid (PIMPLE)", fluidTime_));
        effects.append(coupling_->costs());
    }
    mpm_.summary(Info, effects);
    reportExpectedError(Info, runTime, mpm_.controls().accuracyFront);
}
