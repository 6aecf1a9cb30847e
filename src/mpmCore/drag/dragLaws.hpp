// The drag correlations, one function each (the registry in dragLaw.cpp
// turns each into a selectable DragLaw). Notation: aF = alphaF, aS = 1 - aF, u = |U_f - U_s|,
// Re = aF rhoF u d / muF (superficial slip), Re_p = rhoF u d / muF.
// All coefficients are drag-only ("model A", see dragLaw.hpp); sources and
// normalisation checks in docs/dragLaws.md.
#pragma once
#include "dragLaw.hpp"

namespace mpm {
namespace drag {


// Single sphere, dilute (Schiller & Naumann 1933), no hindrance:
//   beta = 3/4 Cd rhoF u aS / d,  Cd = 24/Re_p (1 + 0.15 Re_p^0.687)
//   (Re_p < 1000), 0.44 above; Re_p WITHOUT aF.
Real schillerNaumann(Real alphaF, Real slip, Real rhoF, Real muF, Real d);

// Wen & Yu (1966):
//   beta = 3/4 Cd aS aF rhoF u / d aF^-2.65, Cd as Schiller-Naumann of Re.
Real wenYu(Real alphaF, Real slip, Real rhoF, Real muF, Real d);

// Ergun (1952) in drag-only form:
//   beta = 150 aS^2 muF / (aF d^2) + 1.75 aS rhoF u / d.
Real ergun(Real alphaF, Real slip, Real rhoF, Real muF, Real d);

// Gidaspow (1994): Ergun for aF < 0.8, Wen-Yu for aF >= 0.8. Discontinuous
// at aF = 0.8 (no blending).
constexpr Real gidaspowSwitch = 0.8;
Real gidaspow(Real alphaF, Real slip, Real rhoF, Real muF, Real d);

// Di Felice (1994):
//   beta = 3/4 Cd rhoF u aS / d aF^(2 - chi),
//   Cd = (0.63 + 4.8/sqrt(Re))^2, chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2).
Real diFelice(Real alphaF, Real slip, Real rhoF, Real muF, Real d);

// Beetstra, van der Hoef & Kuipers (2007), monodisperse:
//   beta = 18 muF aF aS F / d^2,
//   F = 10 aS/aF^2 + aF^2 (1 + 1.5 sqrt(aS))
//     + 0.413 Re/(24 aF^2) (1/aF + 3 aF aS + 8.4 Re^-0.343)
//                         / (1 + 10^(3 aS) Re^(-(1 + 4 aS)/2)).
// F is the drag-only force per sphere over 3 pi muF d (aF u), so no further
// aF factor (see docs/dragLaws.md).
// Beetstra's dimensionless force F(aF, Re) (Re superficial).
Real beetstraForce(Real alphaF, Real Re);
Real beetstra(Real alphaF, Real slip, Real rhoF, Real muF, Real d);

} // namespace drag
} // namespace mpm
