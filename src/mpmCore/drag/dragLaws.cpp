// The drag laws, each written as stokesBeta(aS) times a correction so that
// slip = 0 (Re = 0) is evaluated without 0/0: with Re = aF rhoF u d / muF,
// 3/4 Cd rhoF u aS / d = 18 muF aS / d^2 * (Cd Re)/24 / aF.
#include "dragLaws.hpp"
#include <cmath>

namespace mpm {
namespace drag {

Real wenYu(Real alphaF, Real slip, Real rhoF, Real muF, Real d)
{
    const Real Re = drag::reynolds(alphaF, slip, rhoF, muF, d);
    return drag::stokesBeta(1 - alphaF, muF, d)*drag::cdReSchillerNaumann(Re)/24
          *std::pow(alphaF, -2.65);
}

Real ergun(Real alphaF, Real slip, Real rhoF, Real muF, Real d)
{
    const Real alphaS = 1 - alphaF;
    return 150*alphaS*alphaS*muF/(alphaF*d*d) + 1.75*alphaS*rhoF*slip/d;
}

Real schillerNaumann(Real alphaF, Real slip, Real rhoF, Real muF, Real d)
{
    const Real Rep = drag::reynolds(1, slip, rhoF, muF, d);
    return drag::stokesBeta(1 - alphaF, muF, d)*drag::cdReSchillerNaumann(Rep)/24;
}

Real gidaspow(Real alphaF, Real slip, Real rhoF, Real muF, Real d)
{
    return alphaF < gidaspowSwitch ? ergun(alphaF, slip, rhoF, muF, d)
                                   : wenYu(alphaF, slip, rhoF, muF, d);
}

Real diFelice(Real alphaF, Real slip, Real rhoF, Real muF, Real d)
{
    const Real Re = drag::reynolds(alphaF, slip, rhoF, muF, d);
    const Real x = Re > 0 ? 1.5 - std::log10(Re) : 0;   // exp(-x^2/2) -> 0 as Re -> 0
    const Real chi = Re > 0 ? 3.7 - 0.65*std::exp(-0.5*x*x) : 3.7;
    return drag::stokesBeta(1 - alphaF, muF, d)*drag::cdReDallaValle(Re)/24
          *std::pow(alphaF, 1 - chi);
}

Real beetstraForce(Real alphaF, Real Re)
{
    const Real alphaS = 1 - alphaF, aF2 = alphaF*alphaF;
    Real F = 10*alphaS/aF2 + aF2*(1 + 1.5*std::sqrt(alphaS));
    if (Re > 0)     // the inertial term vanishes like Re^1.157 as Re -> 0
    {
        F += 0.413*Re/(24*aF2)*(1/alphaF + 3*alphaF*alphaS + 8.4*std::pow(Re, -0.343))
            /(1 + std::pow(10.0, 3*alphaS)*std::pow(Re, -0.5*(1 + 4*alphaS)));
    }
    return F;
}

Real beetstra(Real alphaF, Real slip, Real rhoF, Real muF, Real d)
{
    const Real Re = drag::reynolds(alphaF, slip, rhoF, muF, d);
    return drag::stokesBeta(1 - alphaF, muF, d)*alphaF*beetstraForce(alphaF, Re);
}

} // namespace drag
} // namespace mpm
