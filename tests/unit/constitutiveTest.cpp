// Constitutive laws: known stresses against closed forms, objectivity,
// Drucker-Prager return-map admissibility, and makeLaw error messages.
#include "constitutive/constitutiveLaw.hpp"
#include "constitutive/druckerPrager.hpp"
#include "constitutive/linearElastic.hpp"
#include "constitutive/neoHookean.hpp"
#include "constitutive/newtonianFluid.hpp"
#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>

using namespace mpm;

namespace {

using Mat = Eigen::Matrix3d;
using Arr9 = std::array<Real, 9>;
using Arr6 = std::array<Real, 6>;

Arr9 toArray(const Mat& A)
{
    Arr9 a;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[ij(i, j)] = A(i, j);
    return a;
}

Mat symToMat(const Arr6& s)
{
    Mat A;
    A << s[XX], s[XY], s[XZ],
         s[XY], s[YY], s[YZ],
         s[XZ], s[YZ], s[ZZ];
    return A;
}

Arr6 matToSym(const Mat& A)
{
    return {A(0, 0), A(1, 1), A(2, 2), A(0, 1), A(1, 2), A(0, 2)};
}

// Skew tensor W with W v = omega x v.
Mat spin(const Eigen::Vector3d& omega)
{
    Mat W;
    W <<        0, -omega.z(),  omega.y(),
        omega.z(),          0, -omega.x(),
       -omega.y(),  omega.x(),          0;
    return W;
}

// One stress update; Fnew = (I + dt L) Fold as the caller would compute it.
struct Step
{
    Mat L = Mat::Zero();
    Mat Fold = Mat::Identity();
    Real dt = 1.0;
    Arr6 sigma{};
    Real eqPlasticStrain = 0;

    void run(const ConstitutiveLaw& law, const Mat* FnewOverride = nullptr)
    {
        const Arr9 l = toArray(L), fo = toArray(Fold);
        const Arr9 fn = toArray(FnewOverride ? *FnewOverride : Mat((Mat::Identity() + dt*L)*Fold));
        PointKinematics k{l.data(), fo.data(), fn.data(), dt};
        PointStress s{sigma.data(), &eqPlasticStrain};
        law.updateStress(k, s);
    }
};

void expectSymNear(const Arr6& a, const Arr6& b, Real tol, const char* what)
{
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(a[c], b[c], tol) << what << ", component " << c;
}

Real maxAbs(const Arr6& s)
{
    Real m = 0;
    for (Real v : s) m = std::max(m, std::abs(v));
    return m;
}

const Real E = 1.0e7, nu = 0.3, rho = 2000.0;
const Real lambda = E*nu/((1 + nu)*(1 - 2*nu)), mu = E/(2*(1 + nu));

} // namespace

// ---------------------------------------------------------------- linearElastic

TEST(ConstitutiveLinearElastic, UniaxialStrainMatchesHooke)
{
    LinearElastic law(rho, E, nu);
    Step st;
    st.L(0, 0) = 2.0e-3; st.dt = 0.5;           // strain increment 1e-3
    st.run(law);
    const Real eps = 1.0e-3;
    expectSymNear(st.sigma, {(lambda + 2*mu)*eps, lambda*eps, lambda*eps, 0, 0, 0}, 1e-6, "uniaxial strain");
    EXPECT_EQ(st.eqPlasticStrain, 0);
}

TEST(ConstitutiveLinearElastic, VolumetricAndShearMatchHooke)
{
    LinearElastic law(rho, E, nu);
    const Real K = lambda + 2*mu/3, eps = 1.0e-4;
    Step vol;
    vol.L = eps*Mat::Identity();
    vol.run(law);
    expectSymNear(vol.sigma, {3*K*eps, 3*K*eps, 3*K*eps, 0, 0, 0}, 1e-6, "volumetric");

    // Pure shear (symmetric L): sigma_xy = 2 mu D_xy.
    Step shear;
    shear.L(0, 1) = shear.L(1, 0) = eps;
    shear.run(law);
    expectSymNear(shear.sigma, {0, 0, 0, 2*mu*eps, 0, 0}, 1e-6, "shear");
}

TEST(ConstitutiveLinearElastic, JaumannRigidRotationPreservesInvariants)
{
    LinearElastic law(rho, E, nu);
    const Arr6 sigma0{-3.0e5, 1.0e5, 2.0e5, 4.0e4, -7.0e4, 1.5e5};
    const Mat S0 = symToMat(sigma0);
    const Eigen::Vector3d omega(0.3, -0.5, 0.8);
    const Mat W = spin(omega);

    auto rotationError = [&](Real dt)
    {
        Step st;
        st.L = W; st.dt = dt; st.sigma = sigma0;
        st.run(law);
        const Mat S1 = symToMat(st.sigma);
        const Mat R = Eigen::AngleAxisd(omega.norm()*dt, omega.normalized()).toRotationMatrix();

        // The trace is preserved exactly (tr(W S - S W) = 0); the other
        // invariants and the exact rotated stress to O(dt^2).
        const Real scale = S0.norm(), wdt2 = std::pow(omega.norm()*dt, 2);
        EXPECT_NEAR(S1.trace(), S0.trace(), 1e-9*scale);
        const Real I2_0 = 0.5*(std::pow(S0.trace(), 2) - (S0*S0).trace());
        const Real I2_1 = 0.5*(std::pow(S1.trace(), 2) - (S1*S1).trace());
        EXPECT_LE(std::abs(I2_1 - I2_0), 4*wdt2*scale*scale) << "dt " << dt;
        EXPECT_LE(std::abs(S1.determinant() - S0.determinant()), 4*wdt2*std::pow(scale, 3)) << "dt " << dt;
        return (S1 - R*S0*R.transpose()).norm()/scale;
    };

    const Real e1 = rotationError(1.0e-2), e2 = rotationError(0.5e-2);
    EXPECT_LT(e1, 1e-3);
    EXPECT_NEAR(e1/e2, 4.0, 0.2) << "Jaumann update should be second-order accurate per step";
}

TEST(ConstitutiveLinearElastic, WaveSpeedAndNoDtLimit)
{
    LinearElastic law(rho, E, nu);
    EXPECT_NEAR(law.waveSpeed(1.0), std::sqrt((lambda + 2*mu)/rho), 1e-9);
    EXPECT_EQ(law.maxStableDt(0.1), std::numeric_limits<Real>::infinity());
    EXPECT_EQ(law.rho0(), rho);
}

// ------------------------------------------------------------------ neoHookean

TEST(ConstitutiveNeoHookean, UniaxialStretchClosedForm)
{
    NeoHookean law(rho, E, nu);
    for (Real l : {0.7, 0.95, 1.0, 1.3, 2.0})
    {
        Step st;
        const Mat F = Eigen::Vector3d(l, 1, 1).asDiagonal();
        st.run(law, &F);
        const Real lateral = lambda*std::log(l)/l;
        expectSymNear(st.sigma, {mu/l*(l*l - 1) + lateral, lateral, lateral, 0, 0, 0}, 1e-6*E, "stretch");
    }
}

TEST(ConstitutiveNeoHookean, ObjectiveUnderRotation)
{
    NeoHookean law(rho, E, nu);
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(-0.3, 0.3);
    for (int trial = 0; trial < 50; ++trial)
    {
        Mat F = Mat::Identity();
        for (int a = 0; a < 9; ++a) F(a/3, a%3) += u(rng);
        ASSERT_GT(F.determinant(), 0);
        const Mat R = Eigen::Quaterniond::UnitRandom().toRotationMatrix();

        Step plain, rotated;
        const Mat RF = R*F;
        plain.run(law, &F);
        rotated.run(law, &RF);
        const Mat expected = R*symToMat(plain.sigma)*R.transpose();
        expectSymNear(rotated.sigma, matToSym(expected), 1e-8*E, "sigma(RF) = R sigma(F) R^T");
    }
}

TEST(ConstitutiveNeoHookean, SmallStrainMatchesLinearElastic)
{
    NeoHookean hyper(rho, E, nu);
    LinearElastic hypo(rho, E, nu);
    Step a, b;
    a.L << 1e-6, 2e-6, 0, 2e-6, -3e-6, 1e-6, 0, 1e-6, 4e-6;   // symmetric, small
    b.L = a.L;
    a.run(hyper); b.run(hypo);
    expectSymNear(a.sigma, b.sigma, 1e-4*maxAbs(b.sigma), "small strain");
    EXPECT_GT(hyper.waveSpeed(0.8), hyper.waveSpeed(1.0));
    EXPECT_NEAR(hyper.waveSpeed(1.0), std::sqrt((lambda + 2*mu)/rho), 1e-9);
}

// -------------------------------------------------------------- newtonianFluid

TEST(ConstitutiveNewtonianFluid, PressureAtCompression)
{
    const Real K = 2.0e5, gamma = 7, viscosity = 1e-3;
    NewtonianFluid law(1000, K, gamma, viscosity);
    Step st;
    const Mat F = Eigen::Vector3d(0.9, 1, 1).asDiagonal();
    st.run(law, &F);
    const Real p = K*(std::pow(0.9, -gamma) - 1);
    expectSymNear(st.sigma, {-p, -p, -p, 0, 0, 0}, 1e-9*p, "J = 0.9");
    EXPECT_NEAR(law.pressure(0.9), p, 1e-9*p);
}

TEST(ConstitutiveNewtonianFluid, ViscousStressIsTwoMuDevD)
{
    const Real viscosity = 0.5;
    NewtonianFluid law(1000, 2.0e5, 7, viscosity);

    // Simple shear v_x = rate*y: D_xy = rate/2, W != 0 must not matter.
    Step shear;
    shear.L(0, 1) = 3.0; shear.dt = 1e-6;
    const Mat I = Mat::Identity();
    shear.run(law, &I);
    expectSymNear(shear.sigma, {0, 0, 0, 2*viscosity*1.5, 0, 0}, 1e-12, "simple shear");

    // Pure shear (traceless D) and the deviatoric projection of a stretch.
    Step stretch;
    stretch.L(0, 0) = 1.0;
    stretch.run(law, &I);
    expectSymNear(stretch.sigma, {2*viscosity*2.0/3, -2*viscosity/3, -2*viscosity/3, 0, 0, 0}, 1e-12, "dev(D)");
}

TEST(ConstitutiveNewtonianFluid, WaveSpeedAndViscousDt)
{
    const Real K = 2.0e5, gamma = 7, rho0 = 1000, viscosity = 0.5, h = 0.01;
    NewtonianFluid law(rho0, K, gamma, viscosity);
    EXPECT_NEAR(law.waveSpeed(1.0), std::sqrt(K*gamma/rho0), 1e-9);
    EXPECT_NEAR(law.waveSpeed(0.9), std::sqrt(K*gamma/rho0*std::pow(0.9, 1 - gamma)), 1e-9);
    EXPECT_NEAR(law.maxStableDt(h), rho0*h*h/(8*viscosity), 1e-15);
    NewtonianFluid inviscid(rho0, K, gamma, 0);
    EXPECT_EQ(inviscid.maxStableDt(h), std::numeric_limits<Real>::infinity());
}

// --------------------------------------------------------------- druckerPrager

namespace {

// Independent plane-strain Mohr-Coulomb match in q-p form.
Real referenceYield(const Arr6& s, Real phiDeg, Real c)
{
    const Real t = std::tan(phiDeg*M_PI/180), d = std::sqrt(9 + 12*t*t);
    const Mat S = symToMat(s);
    const Real p = -S.trace()/3;
    const Mat dev = S + p*Mat::Identity();
    const Real q = std::sqrt(1.5*(dev.array()*dev.array()).sum());
    return q - 3*std::sqrt(3.0)*t/d*p - 3*std::sqrt(3.0)/d*c;
}

Real qOf(const Arr6& s)
{
    const Mat S = symToMat(s);
    const Mat dev = S - S.trace()/3*Mat::Identity();
    return std::sqrt(1.5*(dev.array()*dev.array()).sum());
}

} // namespace

TEST(ConstitutiveDruckerPrager, PlaneStrainCoefficients)
{
    DruckerPrager law(rho, E, nu, 30, 0, 0);
    EXPECT_NEAR(law.eta(), 3/std::sqrt(13.0), 1e-14);
    EXPECT_NEAR(law.xi(), 3*std::sqrt(3.0)/std::sqrt(13.0), 1e-14);
    EXPECT_EQ(law.etaBar(), 0);
    const Arr6 s{-1e4, -2e4, -3e4, 5e3, -1e3, 2e3};
    DruckerPrager cohesive(rho, E, nu, 30, 500, 10);
    EXPECT_NEAR(cohesive.yieldFunction(s.data()), referenceYield(s, 30, 500), 1e-9);
}

TEST(ConstitutiveDruckerPrager, ElasticBelowYieldEqualsLinearElastic)
{
    DruckerPrager dp(rho, E, nu, 30, 1e3, 5);
    LinearElastic le(rho, E, nu);
    Step a, b;
    a.sigma = b.sigma = {-1e5, -1e5, -1e5, 0, 0, 0};
    a.L << 1e-5, 2e-5, 0, -1e-5, 3e-5, 0, 1e-5, 0, -2e-5;
    b.L = a.L;
    a.run(dp); b.run(le);
    EXPECT_LT(dp.yieldFunction(a.sigma.data()), 0);
    for (int c = 0; c < 6; ++c) EXPECT_EQ(a.sigma[c], b.sigma[c]);
    EXPECT_EQ(a.eqPlasticStrain, 0);
}

TEST(ConstitutiveDruckerPrager, RandomIncrementsStayAdmissible)
{
    const Real c = 1e3;
    DruckerPrager dp(rho, E, nu, 35, c, 10);
    std::mt19937 rng(2024);
    std::uniform_real_distribution<Real> u(-1, 1), logScale(-6, -2);
    Step st;
    st.sigma = {-1e4, -1e4, -1e4, 0, 0, 0};
    int plastic = 0, apex = 0, elastic = 0;
    for (int n = 0; n < 20000; ++n)
    {
        st.L.setZero();
        for (int a = 0; a < 9; ++a) st.L(a/3, a%3) = u(rng);
        // Bias a third of the steps towards expansion to exercise the apex.
        if (n % 3 == 0) st.L += Mat::Identity();
        st.dt = std::pow(10.0, logScale(rng));

        Arr6 trial = st.sigma;
        const Arr9 l = toArray(st.L);
        jaumannElasticUpdate(dp.elasticity(), l.data(), st.dt, trial.data());
        const Real fTrial = dp.yieldFunction(trial.data());
        const Real epsBefore = st.eqPlasticStrain;
        st.run(dp);

        const Real scale = std::max(maxAbs(trial), c);
        const Real f = dp.yieldFunction(st.sigma.data());
        ASSERT_LE(f, 1e-10*scale) << "step " << n;
        if (fTrial > 0)
        {
            ++plastic;
            EXPECT_GT(st.eqPlasticStrain, epsBefore) << "step " << n;
            EXPECT_LE(std::abs(f), 1e-10*scale) << "plastic step ends on the surface, step " << n;
            if (qOf(st.sigma) < 1e-9*scale) ++apex;
        }
        else
        {
            ++elastic;
            EXPECT_EQ(st.eqPlasticStrain, epsBefore) << "step " << n;
            for (int k = 0; k < 6; ++k) EXPECT_EQ(st.sigma[k], trial[k]) << "step " << n;
        }
    }
    EXPECT_GT(plastic, 100);
    EXPECT_GT(apex, 10);
    EXPECT_GT(elastic, 100);
}

TEST(ConstitutiveDruckerPrager, FarBeyondYieldEndsOnSurface)
{
    const Real c = 2e3;
    DruckerPrager dp(rho, E, nu, 30, c, 5);

    // Huge shear from a compressed state: cone return.
    Step shear;
    shear.sigma = {-5e4, -5e4, -5e4, 0, 0, 0};
    shear.L(0, 1) = 1.0; shear.dt = 0.1;
    shear.run(dp);
    const Real scale = E*0.1;
    EXPECT_LT(std::abs(dp.yieldFunction(shear.sigma.data())), 1e-9*scale);
    EXPECT_LT(std::abs(referenceYield(shear.sigma, 30, c)), 1e-9*scale);
    EXPECT_GT(qOf(shear.sigma), 0);
    EXPECT_GT(shear.eqPlasticStrain, 0);

    // Huge expansion: apex return, hydrostatic tension xi c/eta.
    Step tension;
    tension.sigma = shear.sigma;
    tension.L = Mat::Identity(); tension.dt = 0.1;
    tension.run(dp);
    const Real apexStress = dp.xi()*c/dp.eta();
    expectSymNear(tension.sigma, {apexStress, apexStress, apexStress, 0, 0, 0}, 1e-9*scale, "apex");
    EXPECT_LT(std::abs(dp.yieldFunction(tension.sigma.data())), 1e-9*scale);
    EXPECT_GT(tension.eqPlasticStrain, 0);

    // Cohesionless material in tension is stress free.
    DruckerPrager sand(rho, E, nu, 30, 0, 0);
    Step loose;
    loose.L = Mat::Identity(); loose.dt = 0.01;
    loose.run(sand);
    expectSymNear(loose.sigma, {0, 0, 0, 0, 0, 0}, 1e-9*E, "cohesionless tension");
}

TEST(ConstitutiveDruckerPrager, ZeroDilatancyKeepsPressure)
{
    // psi = 0: plastic flow is purely deviatoric, so the cone return keeps
    // p and the equivalent plastic strain increment is f_trial/(3G).
    DruckerPrager dp(rho, E, nu, 30, 0, 0);
    Step st;
    st.sigma = {-1e5, -1e5, -1e5, 0, 0, 0};
    st.L(0, 1) = st.L(1, 0) = 0.5; st.dt = 0.1;
    Arr6 trial = st.sigma;
    const Arr9 l = toArray(st.L);
    jaumannElasticUpdate(dp.elasticity(), l.data(), st.dt, trial.data());
    ASSERT_GT(dp.yieldFunction(trial.data()), 0);
    st.run(dp);
    const Real pTrial = -(trial[0] + trial[1] + trial[2])/3;
    EXPECT_NEAR(-(st.sigma[0] + st.sigma[1] + st.sigma[2])/3, pTrial, 1e-9*pTrial);
    EXPECT_NEAR(st.eqPlasticStrain, dp.yieldFunction(trial.data())/(3*mu), 1e-12);
}

// -------------------------------------------------------------------- registry

namespace {

void expectInvalidMentioning(const std::function<void()>& f, std::initializer_list<const char*> fragments)
{
    try
    {
        f();
        ADD_FAILURE() << "expected std::invalid_argument";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string msg = e.what();
        for (const char* frag : fragments)
            EXPECT_NE(msg.find(frag), std::string::npos) << "'" << frag << "' missing from: " << msg;
    }
}

} // namespace

TEST(ConstitutiveLawRegistry, EveryLawIsConstructibleByName)
{
    const Coefficients values{{"rho", 1000}, {"E", 1e6}, {"nu", 0.25}, {"K", 1e5},
                              {"mu", 1e-3}, {"phi", 30}};
    ASSERT_EQ(availableLaws().size(), 6u);
    for (const LawInfo& info : availableLaws())
    {
        ASSERT_EQ(findLaw(info.name), &info);
        Coefficients c;
        for (const Parameter& p : info.parameters)
            if (p.required) c[p.name] = values.at(p.name);
        if (info.name == "druckerPrager") c["phi"] = 30;   // phi or mu: one of them
        const auto law = makeLaw(info.name, c);
        EXPECT_EQ(info.name, law->typeName());
        EXPECT_EQ(law->rho0(), 1000);
        if (info.name != "dilute") EXPECT_GT(law->waveSpeed(1.0), 0);   // dilute: no stress, no waves
    }
    EXPECT_EQ(findLaw("nope"), nullptr);
}

TEST(ConstitutiveLawRegistry, DefaultsAreApplied)
{
    const auto fluid = makeLaw("newtonianFluid", {{"rho", 1000}, {"K", 1e5}, {"mu", 0}});
    EXPECT_NEAR(fluid->waveSpeed(1.0), std::sqrt(7*1e5/1000), 1e-9);   // gamma = 7
    const auto sand = makeLaw("druckerPrager", {{"rho", 1}, {"E", 1}, {"nu", 0}, {"phi", 30}});
    const auto& dp = dynamic_cast<const DruckerPrager&>(*sand);
    EXPECT_EQ(dp.etaBar(), 0);                                           // psi = 0
    const Real zero[6] = {0, 0, 0, 0, 0, 0};
    EXPECT_EQ(dp.yieldFunction(zero), 0);                                // c = 0
}

// Issue 29: the friction given as the coefficient mobilised in simple shear
// (mu) or as the plane-strain angle (phi). mu = 0.48038 is what phi = 30 deg
// mobilises (docs/druckerPrager.md), so the two are one law; mu = tan 30 deg
// needs phi = 37.76 deg; both, neither, or mu beyond the match's sqrt(3)/2
// are refused.
TEST(ConstitutiveLawRegistry, DruckerPragerFrictionAsMuOrPhi)
{
    const Coefficients base{{"rho", 1}, {"E", 1}, {"nu", 0}};
    auto with = [&](const Coefficients& extra) { Coefficients c = base; for (auto& kv : extra) c.insert(kv); return c; };
    const auto byPhi = makeLaw("druckerPrager", with({{"phi", 30}}));
    const Real mu30 = byPhi->shearStrengthRatio();
    EXPECT_NEAR(mu30, 3*std::tan(M_PI/6)/std::sqrt(9 + 12*std::tan(M_PI/6)*std::tan(M_PI/6)), 1e-15);
    EXPECT_NEAR(mu30, 0.48038, 1e-5);
    const auto byMu = makeLaw("druckerPrager", with({{"mu", mu30}}));
    EXPECT_NEAR(byMu->shearStrengthRatio(), mu30, 1e-14);
    EXPECT_NEAR(dynamic_cast<const DruckerPrager&>(*byMu).eta(), dynamic_cast<const DruckerPrager&>(*byPhi).eta(), 1e-14);
    const Real tan30 = std::tan(M_PI/6);
    EXPECT_NEAR(makeLaw("druckerPrager", with({{"mu", tan30}}))->shearStrengthRatio(), tan30, 1e-14);
    EXPECT_NEAR(DruckerPrager::phiForSimpleShear(tan30), 37.76, 0.01);
    EXPECT_NE(byMu->note().find("mu 0.4804 in simple shear: phi = 30 deg"), std::string::npos) << byMu->note();
    EXPECT_NE(byPhi->note().find("mobilises mu = 0.4804"), std::string::npos) << byPhi->note();
    expectInvalidMentioning([&] { makeLaw("druckerPrager", with({{"phi", 30}, {"mu", 0.5}})); },
        {"druckerPrager", "'phi'", "'mu'", "not both"});
    expectInvalidMentioning([&] { makeLaw("druckerPrager", base); }, {"'phi'", "'mu'", "not neither"});
    expectInvalidMentioning([&] { makeLaw("druckerPrager", with({{"mu", 0.9}})); }, {"'mu'", "0.866"});
    // a dilatancy angle above the friction angle mu implies
    expectInvalidMentioning([&] { makeLaw("druckerPrager", with({{"mu", 0.3}, {"psi", 20}})); }, {"'psi'", "'phi'"});
}

TEST(ConstitutiveLawRegistry, UnknownLawListsValidNames)
{
    expectInvalidMentioning([] { makeLaw("hookean", {}); },
        {"hookean", "linearElastic", "neoHookean", "newtonianFluid", "druckerPrager", "muIRheology"});
}

TEST(ConstitutiveLawRegistry, BadParametersAreNamed)
{
    expectInvalidMentioning([] { makeLaw("linearElastic", {{"rho", 1}, {"nu", 0.3}}); },
        {"linearElastic", "'E'", "missing", "(0, inf)"});
    expectInvalidMentioning([] { makeLaw("linearElastic", {{"rho", 1}, {"E", -5}, {"nu", 0.3}}); },
        {"linearElastic", "'E'", "-5", "(0, inf)"});
    expectInvalidMentioning([] { makeLaw("neoHookean", {{"rho", 1}, {"E", 1}, {"nu", 0.6}}); },
        {"neoHookean", "'nu'", "0.6", "[0, 0.5)"});
    expectInvalidMentioning([] { makeLaw("linearElastic", {{"rho", 1}, {"E", 1}, {"nu", 0.5}}); },
        {"'nu'", "[0, 0.5)"});
    expectInvalidMentioning([] { makeLaw("newtonianFluid", {{"rho", 1}, {"K", 1}, {"mu", -1}}); },
        {"newtonianFluid", "'mu'", "[0, inf)"});
    expectInvalidMentioning([] { makeLaw("druckerPrager", {{"rho", 1}, {"E", 1}, {"nu", 0.2}, {"phi", 90}}); },
        {"druckerPrager", "'phi'", "[0, 90)"});
    expectInvalidMentioning([] { makeLaw("druckerPrager", {{"rho", 1}, {"E", 1}, {"nu", 0.2}, {"phi", 20}, {"psi", 25}}); },
        {"druckerPrager", "'psi'", "'phi'"});
    expectInvalidMentioning([] { makeLaw("linearElastic", {{"rho", 1}, {"E", 1}, {"nu", 0.2}, {"Nu", 0.2}}); },
        {"linearElastic", "'Nu'", "rho, E, nu"});
    expectInvalidMentioning([] { makeLaw("linearElastic", {{"rho", std::nan("")}, {"E", 1}, {"nu", 0.2}}); },
        {"'rho'"});
}

// Stored energy used by the energy diagnostics: consistent with each law's
// stress (dW/dF = P for the hyperelastic law, -p for the fluid, sigma^2/2E
// for uniaxial stress in the hypoelastic ones).
TEST(ConstitutiveStoredEnergy, ConsistentWithStress)
{
    const Real I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    {
        auto law = makeLaw("linearElastic", {{"rho", 1}, {"E", 200}, {"nu", 0.25}});
        const Real sigma[6] = {3.0, 0, 0, 0, 0, 0};
        EXPECT_NEAR(law->storedEnergy(sigma, I), 9.0/(2*200), 1e-14);
        auto dp = makeLaw("druckerPrager", {{"rho", 1}, {"E", 200}, {"nu", 0.25}, {"phi", 30}});
        EXPECT_NEAR(dp->storedEnergy(sigma, I), 9.0/(2*200), 1e-14);
    }
    {
        auto law = makeLaw("neoHookean", {{"rho", 1}, {"E", 100}, {"nu", 0.3}});
        auto W = [&](Real l) { const Real F[9] = {l, 0, 0, 0, 1, 0, 0, 0, 1}; return law->storedEnergy(nullptr, F); };
        const Real l = 1.2, e = 1e-6;
        const Real F[9] = {l, 0, 0, 0, 1, 0, 0, 0, 1}, L0[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
        Real sig[6] = {0, 0, 0, 0, 0, 0}, ep = 0;
        PointKinematics k{L0, I, F, 0.0};
        PointStress s{sig, &ep};
        law->updateStress(k, s);
        // P_11 = J sigma_11 / l with J = l
        EXPECT_NEAR((W(l + e) - W(l - e))/(2*e), sig[XX], 1e-6);
        EXPECT_NEAR(W(1.0), 0.0, 1e-15);
    }
    {
        auto law = makeLaw("newtonianFluid", {{"rho", 1}, {"K", 10}, {"gamma", 7}, {"mu", 0}});
        auto W = [&](Real J) { const Real F[9] = {J, 0, 0, 0, 1, 0, 0, 0, 1}; return law->storedEnergy(nullptr, F); };
        const Real J = 0.95, e = 1e-6;
        const Real p = 10*(std::pow(J, -7.0) - 1);
        EXPECT_NEAR((W(J + e) - W(J - e))/(2*e), -p, 1e-5);
    }
}
