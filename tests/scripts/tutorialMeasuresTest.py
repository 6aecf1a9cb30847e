#!/usr/bin/env python3
"""The measures the tutorials' scripts report, on made-up data whose answer
is known: the column's fronts and bulk measures (plotProfile.py,
plotRunout.py), its failure wedge, spreading layer's shear zone and tail's
deceleration (diagnoseFront.py) and the silo's Beverloo fits
(plotDischarge.py). The case tests check the runs; these
check that the numbers printed from them measure what they say."""
import os
import sys
import unittest

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path[:0] = [os.path.join(ROOT, "etc", "python"),
                os.path.join(ROOT, "tutorials", "mpm", "granularColumnCollapse"),
                os.path.join(ROOT, "tutorials", "mpm", "siloDischarge")]

import diagnoseFront   # noqa: E402
import plotDischarge   # noqa: E402
import plotProfile     # noqa: E402
import plotRunout      # noqa: E402


def cloud(xs, ys=None):
    xs = np.asarray(xs, dtype=float)
    return np.column_stack([xs, np.zeros_like(xs) if ys is None else ys, np.zeros_like(xs)])


class ColumnFronts(unittest.TestCase):
    def test_front_ignores_a_light_point_thrown_ahead(self):
        # 1000 points of mass 1 in [0, 1), one of mass 0.5 at x = 10: the
        # 99.9 % front stays in the deposit, the farthest point does not
        x = cloud(list(np.linspace(0, 0.999, 1000)) + [10.0])
        m = np.array([1.0]*1000 + [0.5])
        front = plotProfile.mass_front(x, m)
        self.assertLess(front, 1.0)
        self.assertGreater(front, 0.99)

    def test_front_follows_the_mass_not_the_count(self):
        # nine light points behind one that holds 91 % of the mass: 90 % of
        # the mass lies behind the heavy point only
        x = cloud(np.arange(10.0))
        m = np.array([1.0]*9 + [91.0])
        self.assertEqual(plotProfile.mass_front(x, m, 0.9), 9.0)
        self.assertEqual(plotProfile.mass_front(x, np.ones(10), 0.5), 4.0)

    def test_travel_is_the_mass_weighted_displacement(self):
        x0 = cloud([0.0, 0.1, 0.2])
        m = np.array([1.0, 1.0, 2.0])
        a0 = 0.2
        # everything moves by 0.3: travel 0.3/a0, front90 from 0.2 to 0.5
        front90, travel = plotRunout.bulk_measures(x0, m, x0 + [0.3, 0, 0], m, a0)
        self.assertAlmostEqual(travel, 1.5, places=12)
        self.assertAlmostEqual(front90, (0.5 - a0)/a0, places=12)
        # only the heavy point moves by 0.4: the centre of mass by 0.4*2/4
        x1 = x0.copy()
        x1[2, 0] += 0.4
        self.assertAlmostEqual(plotRunout.bulk_measures(x0, m, x1, m, a0)[1], 0.2/a0, places=12)

    def test_run_names(self):
        self.assertEqual(plotRunout.run_parameters("sweep/sand_a2_h0.005"), ("sand", 2.0, 0.005))
        self.assertEqual(plotRunout.run_parameters("sweep/glassBeads_a0.5_h0.01_E2e5_geostatic_FLIP/"),
                         ("glassBeads_E2e5_geostatic_FLIP", 0.5, 0.01))
        # a run with other points per cell is another series, not a resolution
        self.assertEqual(plotRunout.run_parameters("sweep/sand_a2_h0.01_FLIP_ppc4"), ("sand_FLIP_ppc4", 2.0, 0.01))

    def test_fronts_of_a_uniform_deposit(self):
        # 10000 equal points evenly over [a0, 3 a0): the front of a share q of
        # the mass is at a0 + 2 a0 q, so (L_q - a0)/a0 = 2 q
        a0 = 0.2
        x = cloud(a0 + 2*a0*(np.arange(10000) + 0.5)/10000)
        for q, value in zip(plotRunout.FRONT_FRACTIONS, plotRunout.fronts(x, np.ones(10000), a0)):
            self.assertAlmostEqual(value, 2*q, delta=2e-4)
        # the far half twice as heavy: the near half holds 1/3 of the mass, so
        # the 90 % front lies 85 % into the far half, x = 2 a0 + 0.85 a0
        m = np.where(x[:, 0] >= 2*a0, 2.0, 1.0)
        self.assertAlmostEqual(plotRunout.fronts(x, m, a0, (0.9,))[0], 1.85, delta=2e-4)

    def test_halvings_pair_only_halved_cells(self):
        by_h = [(0.005, 3.9), (0.02, 2.0), (0.01, 3.0), (0.003, 4.0)]
        self.assertEqual([(h1, h2, v1, v2) for h1, h2, v1, v2, _ in plotRunout.halvings(by_h)],
                         [(0.02, 0.01, 2.0, 3.0), (0.01, 0.005, 3.0, 3.9)])
        self.assertEqual([round(c, 12) for *_, c in plotRunout.halvings(by_h)], [0.5, 0.3])
        # the fronts table passes each run's fronts as one array: a change per front
        fronts = [(0.005, np.array([3.0, 6.0])), (0.01, np.array([2.0, 4.0]))]
        (h1, h2, _, _, change), = plotRunout.halvings(fronts)
        self.assertEqual((h1, h2), (0.01, 0.005))
        self.assertEqual(list(change), [0.5, 0.5])

    def test_lube_law(self):
        self.assertAlmostEqual(plotRunout.lube(2.0), 2.4)
        self.assertAlmostEqual(plotRunout.lube(8.0), 1.9*4.0)


class ShearZone(unittest.TestCase):
    def profile(self, z1, z2, U=1.0, depth=0.1, bins=400):
        """A static base below z1, a plug at U above z2, linear between."""
        z = (np.arange(bins) + 0.5)*depth/bins
        return depth, U*np.clip((z - z1)/(z2 - z1), 0, 1)

    def test_width_of_a_linear_band(self):
        depth, ux = self.profile(0.03, 0.07)
        self.assertAlmostEqual(diagnoseFront.shear_zone(depth, ux), 0.8*0.04, delta=depth/400)

    def test_width_scales_with_the_band_not_the_depth(self):
        thin = diagnoseFront.shear_zone(*self.profile(0.05, 0.06))
        thick = diagnoseFront.shear_zone(*self.profile(0.02, 0.08))
        self.assertAlmostEqual(thick/thin, 6.0, delta=0.1)

    def test_a_slower_surface_does_not_move_the_band(self):
        depth, ux = self.profile(0.03, 0.07)
        z = (np.arange(len(ux)) + 0.5)*depth/len(ux)
        top = z > 0.08
        ux[top] = 1.0 - 2.0*(z[top] - 0.08)/0.02*0.1   # down to 0.8 at the surface
        self.assertAlmostEqual(diagnoseFront.shear_zone(depth, ux), 0.8*0.04, delta=depth/400)

    def test_a_dip_below_the_band_does_not_shorten_it(self):
        depth, ux = self.profile(0.03, 0.07)
        ux[:20] = -0.2          # the base sliding back a little
        self.assertAlmostEqual(diagnoseFront.shear_zone(depth, ux), 0.8*0.04, delta=depth/400)


class FailureWedge(unittest.TestCase):
    h = 0.01

    def line(self, y, ramp=(0.3, 0.5), speed=0.8, n=2001):
        """Points on the line y over x in [0, 1]: at rest before the ramp,
        sliding at `speed` along (1, -1)/sqrt(2) beyond it, linear between."""
        xs = np.linspace(0.0, 1.0, n)
        s = speed*np.clip((xs - ramp[0])/(ramp[1] - ramp[0]), 0, 1)
        return cloud(xs, np.full(n, y)), np.column_stack([s, -s, np.zeros(n)])/np.sqrt(2)

    def test_speed_and_width_of_a_linear_ramp(self):
        x, u = self.line(0.1)
        wedge, width = diagnoseFront.wedge_and_width(x, u, 0.1, self.h)
        self.assertAlmostEqual(wedge, 0.8, places=9)        # the speed, not u_x
        self.assertAlmostEqual(width, 0.8*0.2, delta=1e-3)  # 10 % to 90 % of the ramp

    def test_points_off_the_line_are_left_out(self):
        x, u = self.line(0.1)
        xo, uo = self.line(0.1 + self.h, ramp=(0.0, 0.05), speed=3.0)
        wedge, width = diagnoseFront.wedge_and_width(np.vstack([x, xo]), np.vstack([u, uo]), 0.1, self.h)
        self.assertAlmostEqual(wedge, 0.8, places=9)
        self.assertAlmostEqual(width, 0.16, delta=1e-3)


class TailDeceleration(unittest.TestCase):
    def rows(self, decel, peak=1.6, t_peak=0.3):
        """front_history rows every 0.05 s: the tail accelerates to `peak` at
        t_peak, then slows at `decel` m/s^2 until it stops."""
        t = np.round(np.arange(0.0, 1.1001, 0.05), 10)
        u = np.where(t <= t_peak, peak*t/t_peak, np.maximum(peak - decel*(t - t_peak), 0.0))
        return [(ti, 0.2 + ui*ti, ui) for ti, ui in zip(t, u)]

    def test_deceleration_after_the_peak(self):
        peak, end, decel = diagnoseFront.tail_deceleration(self.rows(3.0))
        self.assertEqual((peak[0], end[0]), (0.3, 0.55))
        self.assertAlmostEqual(decel, 3.0, places=9)
        # a slower stop is measured as such, over the same window
        self.assertAlmostEqual(diagnoseFront.tail_deceleration(self.rows(2.0, t_peak=0.4))[2], 2.0, places=9)


class Beverloo(unittest.TestCase):
    D = np.array([0.04, 0.06, 0.08, 0.12, 0.16])

    def rates(self, C, delta, n=1.5):
        return C*plotDischarge.RHO*np.sqrt(plotDischarge.G)*(self.D - delta)**n

    def test_constant_and_exponent_of_an_exact_law(self):
        W = self.rates(1.03, 0.0)
        np.testing.assert_allclose(plotDischarge.beverlooC(self.D, W), 1.03, rtol=1e-12)
        n, lnA, residual = plotDischarge.exponentFit(self.D, W)
        self.assertAlmostEqual(n, 1.5, places=10)
        self.assertAlmostEqual(np.exp(lnA), 1.03*plotDischarge.RHO*np.sqrt(plotDischarge.G), places=6)
        self.assertLess(residual, 1e-20)

    def test_other_exponent_is_measured_not_assumed(self):
        self.assertAlmostEqual(plotDischarge.exponentFit(self.D, self.rates(1.0, 0.0, n=1.7))[0], 1.7, places=10)

    def test_excluded_width_is_recovered(self):
        W = self.rates(1.2, 0.012)
        # without it the exponent is biased upwards ...
        self.assertGreater(plotDischarge.exponentFit(self.D, W)[0], 1.6)
        # ... with it the law is found again, to the scan's step
        n, lnA, delta = plotDischarge.excludedWidthFit(self.D, W)
        step = 0.98*self.D.min()/980
        self.assertAlmostEqual(delta, 0.012, delta=step)
        self.assertAlmostEqual(n, 1.5, delta=0.01)
        np.testing.assert_allclose(plotDischarge.beverlooC(self.D, W, delta), 1.2, rtol=0.01)


class BadInput(unittest.TestCase):
    """Scripts given nothing to measure say so and exit non-zero, with no
    traceback."""
    def run_main(self, module, argv):
        saved = sys.argv
        sys.argv = [module.__name__ + ".py"] + argv
        try:
            with self.assertRaises(SystemExit) as stop:
                module.main()
        finally:
            sys.argv = saved
        return str(stop.exception.code)

    def test_silo_without_a_finished_run(self):
        import tempfile
        with tempfile.TemporaryDirectory() as empty:
            message = self.run_main(plotDischarge, ["--no-plot", empty])
        self.assertIn("no finished run among " + empty, message)
        self.assertIn("postProcessing/openBoundaries", message)

    def test_front_diagnosis_without_runs(self):
        self.assertIn("Usage: diagnoseFront.py RUN...", self.run_main(diagnoseFront, []))

    def test_sweep_rejects_a_bad_option_value_before_running(self):
        import subprocess
        sweep = os.path.join(ROOT, "tutorials", "mpm", "granularColumnCollapse", "sweepAspectRatio")
        for argv, message in ((["-ppc", "x"], "-ppc x: give a whole number of points per cell and direction, 1 to 9"),
                              (["-ppc", "10"], "-ppc 10: give a whole number of points per cell and direction"),
                              (["-transfer", "MLS"], "-transfer MLS: valid transfers are APIC PIC FLIP")):
            done = subprocess.run(["bash", sweep, "-laws", "noSuchMaterial"] + argv,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
            self.assertEqual(done.returncode, 1, argv)
            self.assertIn("sweepAspectRatio: " + message, done.stderr)
            # stopped at the option, before any run directory was made
            self.assertNotIn("column a =", done.stdout)


if __name__ == "__main__":
    unittest.main(verbosity=2)
