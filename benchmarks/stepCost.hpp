// Bytes moved and flops per point-step of the step that particleThroughput
// times (3D, USL, PIC/FLIP, lumped mass, linear elastic, no coupling), to
// put its throughput as a fraction of the machine's ceilings (ceilings.hpp).
//
// Counting method (a model, not a hardware count):
//  - Bytes: every point array a phase reads or writes counts once per
//    point-step (8 bytes a double, 4 the material index), as STREAM counts
//    (no write-allocate). The stencil's grid accesses are taken as cache
//    hits (a binning block's nodes are reused by its points); the nodal
//    phase's arrays count once per active node, spread over the points.
//  - Flops: from the kernels' source expressions: a multiply, add, subtract
//    or divide is 1, a fused multiply-add 2 (counted as its multiply and
//    add); floor, min/max, comparisons, isfinite and index arithmetic are
//    not counted. Per-point work is counted once; per-node work of the
//    stencil loops times the stencil's nodes.
// The per-phase counts are listed below with the arrays or expressions.
#pragma once
#include "shapeFunctions/shapeFunctions.hpp"
#include "types.hpp"

namespace mpm::bench {

struct StepCost
{
    double bytes = 0;   // per point-step
    double flops = 0;   // per point-step
};

inline StepCost stepCost(ShapeKind shape, Index points, Index activeNodes)
{
    const int W = kernelWidth(shape);
    const double nodes = double(W)*W*W;
    const double nodesPerPoint = double(activeNodes)/double(points);

    // Bytes per point-step, by phase
    const double binning = 8*(3 + 1 + 2);      // read x; write key, read it back; write order
    const double p2g = 8*(3 + 3 + 1 + 1 + 6);  // read x, v, mass, volume, sigma
    const double g2p = 8*(3 + 3) + 8*(3 + 3 + 9); // read x, v; write v, dx, L
    const double stress = 8*(9 + 9 + 6 + 1) + 4 + 8*(9 + 6 + 1); // read F, L, sigma, volume0,
                                               // material; write F, sigma, volume
    const double move = 8*(3 + 3 + 3) + 8*3;   // read x, v, dx; write x
    // Nodal phase, per active node: zeroing 14 arrays, gravity (read mass,
    // read+write force 3), velocityOld = p/m (read 4, write 3), rhs = p +
    // dt f (read 6, write 3), v = rhs/m (read 4, write 3), ghosts/friction
    // (read+write v 3 x 2)
    const double nodal = 8*(14 + 7 + 7 + 9 + 7 + 6);

    // Flops per point-step. Stencil setup per axis (xi, weights, dw*invh,
    // local offset): LH 9, QBS 19, CBS 40; per node N and gradN: 4 plus
    // 3/W for the (j,k) products.
    const double setupPerAxis = shape == ShapeKind::linearHat ? 9 : shape == ShapeKind::quadraticBSpline ? 19 : 40;
    const double stencilNode = 4 + 3.0/W;
    // P2G per node: mass and volume 4, momentum 7, force 3 x 7
    const double p2gNode = 4 + 7 + 21;
    // G2P per node: vPic 6, FLIP increment 9, velocity gradient 18; per
    // point: velocity blend 12, displacement 3
    const double g2pNode = 6 + 9 + 18;
    // Stress per point (linear elastic): dt L 9, F update 54, det 14,
    // Jaumann update 78 (W 6, W S 27, D 6, spin 6, lambda tr D 3, sigma
    // 30), volume 1
    const double stressFlops = 9 + 54 + 14 + 78 + 1;
    // Binning 6 ((x - o)/h per axis), move 3, nodal per node ~20
    StepCost c;
    c.bytes = binning + p2g + g2p + stress + move + nodal*nodesPerPoint;
    c.flops = 2*3*setupPerAxis + nodes*(p2gNode + g2pNode + 2*stencilNode) + 15 + stressFlops
            + 6 + 3 + 20*nodesPerPoint;
    return c;
}

} // namespace mpm::bench
