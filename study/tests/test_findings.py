"""study/tools/findings.py, the statistics behind study/FINDINGS.md's verdicts, on small made-up
tables: cells of a few beds' V_y, one bed's sigma given."""
import math
import unittest

from tests.test_study_tools import load_tool

findings = load_tool("findings")
compare, judged, finding_verdict = findings.compare, findings.judged, findings.finding_verdict

SIGMA = 0.05   # one bed's standard deviation of these made-up scales


class CellNumbersTest(unittest.TestCase):
    def test_mean_sample_deviation_and_standard_error(self):
        self.assertAlmostEqual(findings.sd([1.0, 2.0, 3.0]), 1.0)   # n - 1
        m, se = findings.stats([1.0, 2.0, 3.0])
        self.assertAlmostEqual(m, 2.0)
        self.assertAlmostEqual(se, 1 / math.sqrt(3))

    def test_one_bed_has_a_mean_and_no_standard_error(self):
        m, se = findings.stats([0.2])
        self.assertEqual(m, 0.2)
        self.assertTrue(math.isnan(se))

    def test_a_scales_sigma_is_its_most_scattered_cell(self):
        self.assertAlmostEqual(findings.largest_sd([[0.0, 0.1], [0.0, 0.3], [1.0, 1.0, 1.0]]), 0.3 / math.sqrt(2))


class ScatterRuleTest(unittest.TestCase):
    """Which sigma a cell is judged by (side_sigma)."""

    def test_fewer_beds_than_the_rule_take_the_scales_sigma_however_they_scatter(self):
        self.assertEqual(findings.side_sigma([0.0, 1.0], SIGMA), SIGMA)

    def test_three_beds_that_scatter_more_take_their_own(self):
        values = [0.0, 0.5, 1.0]
        self.assertEqual(findings.OWN_SCATTER_BEDS, 3)
        self.assertAlmostEqual(findings.side_sigma(values, SIGMA), 0.5)

    def test_three_beds_that_scatter_less_keep_the_scales(self):
        self.assertEqual(findings.side_sigma([0.10, 0.11, 0.12], SIGMA), SIGMA)

    def test_own_scatter_turns_a_resolved_difference_into_one_within(self):
        tight = compare("a", [0.2, 0.2], None, +1)                # se = 0.05 / sqrt(2): 5.7 se
        loose = compare("a", [-0.3, 0.2, 0.7], None, +1)          # same mean, sd 0.5: 0.7 se
        self.assertEqual(judged(tight, SIGMA)[2], "for")
        self.assertEqual(judged(loose, SIGMA)[1], 0.7)
        self.assertEqual(judged(loose, SIGMA)[2], "within")


class ComparisonTest(unittest.TestCase):
    def test_against_zero_counts_the_mean_in_standard_errors_the_papers_way(self):
        diff, z, outcome = judged(compare("sinks", [-0.1], None, -1), SIGMA)
        self.assertAlmostEqual(diff, -0.1)
        self.assertEqual((z, outcome), (2.0, "for"))
        self.assertEqual(judged(compare("rises", [-0.1], None, +1), SIGMA)[1:], (-2.0, "against"))

    def test_two_cells_add_their_standard_errors(self):
        # se = 0.05 sqrt(1/2 + 1/1) = 0.0612; difference 0.1: 1.6 se, within
        diff, z, outcome = judged(compare("a above b", [0.15, 0.15], [0.05], +1), SIGMA)
        self.assertAlmostEqual(diff, 0.1)
        self.assertEqual((z, outcome), (1.6, "within"))

    def test_judged_as_printed_to_a_tenth(self):
        # 1.96 standard errors prints as 2.0, and is judged as what it prints
        self.assertEqual(judged(compare("a", [1.96 * SIGMA], None, +1), SIGMA)[1:], (2.0, "for"))
        self.assertEqual(judged(compare("a", [1.94 * SIGMA], None, +1), SIGMA)[1:], (1.9, "within"))

    def test_a_cell_without_results_makes_no_comparison(self):
        self.assertIsNone(compare("a", [], None, +1))
        self.assertIsNone(compare("a", [0.1], [], +1))
        self.assertEqual(compare("a", [0.1], None, +1).b, [])


class VerdictTest(unittest.TestCase):
    """A finding's verdict at one scale, from made-up cells."""

    def test_reproduced_every_comparison_the_papers_way(self):
        comparisons = [compare("sinks", [-0.20, -0.22], None, -1), compare("rises", [0.3], None, +1)]
        self.assertEqual(finding_verdict(SIGMA, comparisons), "reproduced")

    def test_not_reproduced_one_against_outweighs_any_number_for(self):
        comparisons = [compare("rises", [0.3], None, +1)] * 5 + [compare("sinks", [0.2], None, -1)]
        self.assertEqual(finding_verdict(SIGMA, comparisons), "not reproduced")

    def test_not_resolved_when_the_scatter_is_larger_than_the_difference(self):
        comparisons = [compare("rises", [0.3], None, +1), compare("a above b", [0.12], [0.10], +1)]
        self.assertEqual(judged(comparisons[1], SIGMA)[2], "within")
        self.assertEqual(finding_verdict(SIGMA, comparisons), "not resolved")

    def test_not_judged_when_missing_data_leaves_no_comparison_and_a_note_says_why(self):
        missing = [compare("rises", [], None, +1), compare("a above b", [0.2], [], +1)]
        self.assertEqual(finding_verdict(SIGMA, missing, "not judged: its periods stop below the maxima"), "not judged")

    def test_not_measured_when_nothing_bears_on_it(self):
        self.assertEqual(finding_verdict(SIGMA, []), "not measured")
        self.assertEqual(finding_verdict(SIGMA, [None, None]), "not measured")

    def test_every_verdict_is_one_of_the_named_five(self):
        cases = [[], [compare("a", [0.3], None, +1)], [compare("a", [0.3], None, -1)], [compare("a", [0.0], None, +1)]]
        said = {finding_verdict(SIGMA, c) for c in cases} | {finding_verdict(SIGMA, [], "why")}
        self.assertEqual(said, set(findings.VERDICTS))

    def test_missing_cells_are_left_out_of_a_verdict(self):
        self.assertEqual(finding_verdict(SIGMA, [None, compare("rises", [0.3], None, +1)]), "reproduced")


class FindingsComparisonsTest(unittest.TestCase):
    """The comparisons each finding makes from a shape's cells by period."""

    def test_sinks_then_rises_takes_the_shortest_and_the_largest_of_the_longer(self):
        by_period = {2.0: [-0.1], 3.0: [0.05], 4.0: [0.2, 0.22], 5.0: [0.1]}
        sinks, rises = findings.sinks_then_rises("A = 5", "disk", by_period)
        self.assertEqual((sinks.label, sinks.a, sinks.direction), ("disk, A = 5: sinks at T = 2, its shortest", [-0.1], -1))
        self.assertEqual(rises.label, "disk, A = 5: rises at T = 4, its largest of T = 3-5")
        self.assertEqual(rises.a, [0.2, 0.22])

    def test_one_period_only_makes_no_comparison(self):
        self.assertEqual(findings.sinks_then_rises("A = 5", "disk", {3.0: [0.1]}), [])
        self.assertEqual(findings.has_maximum("A = 5", "disk", {3.0: [0.1]}), [])

    def test_has_maximum_only_where_it_rises_and_against_when_the_longest_is_largest(self):
        self.assertEqual(findings.has_maximum("A = 5", "triangle", {3.0: [-0.1], 5.0: [-0.05]}), [])
        (c,) = findings.has_maximum("A = 5", "disk", {3.0: [0.1], 5.0: [0.3]})
        self.assertEqual((c.a, c.b), ([0.1], [0.3]))
        self.assertEqual(judged(c, SIGMA)[2], "against")

    def test_in_order_compares_neighbours_that_have_results(self):
        by_shape = {"disk": [0.3], "rect_narrow": [], "square": [0.1], "triangle": [-0.1]}
        labels = [c.label for c in findings.in_order("A = 5", 3.0, by_shape)]
        self.assertEqual(labels, ["A = 5, T = 3: disk above square", "A = 5, T = 3: square above triangle"])

    def test_friction_steps_leave_a_missing_mu_out(self):
        steps = findings.friction_steps("disk", {0.0: [0.1], 0.1: [], 0.3: [0.2]})
        self.assertEqual(steps, [None, None])
        (c,) = findings.friction_steps("disk", {0.1: [0.1], 0.3: [0.2]})
        self.assertEqual((c.label, c.a, c.b), ("disk: mu = 0.3 above mu = 0.1", [0.2], [0.1]))

    def test_small_amplitudes_compare_a3_with_1_and_half(self):
        cs = findings.small_amplitudes("disk", 5.0, {3.0: [0.2], 1.0: [0.0]}, +1)
        self.assertEqual(cs[0].label, "disk, T = 5: A = 3 above A = 1")
        self.assertIsNone(cs[1])   # A = 0.5 not run

    def test_table1_range_takes_the_ends_or_the_nearest_period_beyond(self):
        cs = findings.table1_range("square", {2.5: [-0.1], 3.5: [0.0], 5.0: [0.2]}, (3.0, 4.0))
        self.assertEqual([(c.label, c.direction) for c in cs],
                         [("square: not rising at T = 2.5 (below the paper's lower end, 3)", -1),
                          ("square: rising at T = 5 (above the paper's upper end, 4)", +1)])
        cs = findings.table1_range("disk", {2.5: [-0.1], 3.0: [0.2]}, (2.5, 3.0))
        self.assertEqual([c.label for c in cs], ["disk: not rising at T = 2.5 (the paper's lower end)",
                                                 "disk: rising at T = 3 (the paper's upper end)"])
        # no period at or below the lower end: only the rising side
        self.assertEqual(findings.table1_range("disk", {3.5: [0.2]}, (2.0, 3.0)),
                         [compare("disk: rising at T = 3.5 (above the paper's upper end, 3)", [0.2], None, +1)])


class BracketTest(unittest.TestCase):
    """Where V_y leaves zero, and how that stands against the paper's range."""

    def test_first_rise_is_the_first_period_resolved_above_zero(self):
        cells = [(2.0, [-0.2]), (2.5, [0.05]), (3.0, [0.15, 0.16]), (4.0, [0.3])]
        self.assertEqual(findings.first_rise(cells, SIGMA), (2.5, 3.0))

    def test_a_zero_crossing_inside_the_error_is_not_a_rise(self):
        # the mean crosses zero between T = 2.5 and 3, but +0.06 on one bed is 1.2 se: not rising
        cells = [(2.5, [-0.02]), (3.0, [0.06])]
        self.assertEqual(findings.first_rise(cells, SIGMA), (None, None))
        self.assertIsNone(findings.first_resolved(cells, SIGMA))

    def test_rising_at_the_shortest_period_has_no_lower_end(self):
        self.assertEqual(findings.first_rise([(2.0, [0.2]), (3.0, [0.3])], SIGMA), (None, 2.0))

    def test_first_resolved_goes_either_way_and_says_which(self):
        cells = [(0.5, [0.01]), (1.0, [-0.02]), (3.0, [-0.2]), (5.0, [0.3])]
        self.assertEqual(findings.first_resolved(cells, SIGMA), (1.0, 3.0, -1))
        self.assertEqual(findings.first_resolved([(3.0, [0.2])], SIGMA), (None, 3.0, +1))

    def test_against_the_papers_range(self):
        paper = (3.0, 4.0)
        self.assertEqual(findings.against_range(3.0, 4.0, paper), "**yes**: the paper's range")
        self.assertEqual(findings.against_range(3.0, 3.5, paper), "**yes**: inside the paper's range")
        self.assertEqual(findings.against_range(3.5, 5.0, paper), "overlaps the paper's range")
        self.assertEqual(findings.against_range(2.5, 3.0, paper), "**no**: below the paper's range")
        self.assertEqual(findings.against_range(4.0, 5.0, paper), "**no**: above the paper's range")
        self.assertEqual(findings.against_range(None, None, paper), "**no**: no rise at any period run")
        self.assertEqual(findings.against_range(None, 3.5, paper), "rises already at the shortest period run")
        # rising already where the paper's intruder does not rise yet: below its range, whatever lies below
        self.assertEqual(findings.against_range(None, 3.0, paper), "**no**: below the paper's range")

    def test_the_papers_side_of_zero_at_a_period(self):
        paper = (3.0, 4.0)
        self.assertEqual([findings.paper_side(t, paper) for t in (2.5, 3.0, 3.5, 4.0, 5.0)], [-1, -1, 0, +1, +1])


class PairedChangesTest(unittest.TestCase):
    def test_pooled_deviation_of_changes_uses_groups_of_two_beds_or_more(self):
        spread, dof, groups = findings.pooled_sd([[0.1, 0.3], [0.0, 0.2, 0.4], [5.0]])
        # sum of squares 0.02 + 0.08 over (1 + 2) degrees of freedom; the one-bed group left out
        self.assertEqual((dof, groups), (3, 2))
        self.assertAlmostEqual(spread, math.sqrt(0.1 / 3))
        self.assertEqual(findings.pooled_sd([[0.1], [0.2]]), (0.0, 0, 0))

    def test_a_change_is_resolved_at_two_standard_errors_of_the_pooled_deviation(self):
        self.assertTrue(findings.change_resolved([0.1, 0.1], 0.07))      # 0.1 >= 2 x 0.0495
        self.assertFalse(findings.change_resolved([0.1, 0.1], 0.08))     # 0.1 <  2 x 0.0566
        self.assertFalse(findings.change_resolved([], 0.05))


class ShapeScatterTest(unittest.TestCase):
    """One bed's sigma per shape: pooled over the shape's cells of two beds or more (shape_scatter)."""

    def test_pooled_over_a_shapes_cells_with_their_degrees_of_freedom(self):
        sigma, dof, cells = findings.pooled_scatter([[0.10, 0.12], [0.0, 0.01, 0.02], [0.5]])
        # squares 0.0002 + 0.0002 over (1 + 2) degrees of freedom; the one-bed cell tells nothing
        self.assertEqual((dof, cells), (3, 2))
        self.assertAlmostEqual(sigma, math.sqrt(0.0004 / 3))

    def test_a_quiet_shape_is_not_judged_by_another_shapes_scatter(self):
        # the largest-sd rule gives every shape the triangle's 0.1 / sqrt(2); pooled by shape the square
        # keeps its own, five times smaller, and the triangle's is its own
        cells = {"square": [[0.020, 0.022], [0.016, 0.018], [0.030, 0.032, 0.034]], "triangle": [[-0.05, -0.15]]}
        largest = findings.largest_sd([c for shape in cells.values() for c in shape])
        scatter = findings.shape_scatter(cells)
        self.assertAlmostEqual(largest, 0.1 / math.sqrt(2))
        self.assertAlmostEqual(scatter["square"].sigma, math.sqrt((0.000002 + 0.000002 + 0.000008) / 4))
        self.assertEqual((scatter["square"].dof, scatter["square"].cells, scatter["square"].own), (4, 3, True))
        self.assertLess(scatter["square"].sigma, largest / 5)
        self.assertAlmostEqual(scatter["triangle"].sigma, largest)
        self.assertEqual(scatter["triangle"].dof, 1)
        # the same cell judged by each: 2 beds at +0.019 from zero
        rising = compare("square rises", [0.017, 0.021], None, +1)
        self.assertEqual(judged(rising, largest)[1:], (0.4, "within"))
        self.assertEqual(judged(rising, scatter["square"].sigma)[2], "for")

    def test_a_shape_without_a_cell_of_two_beds_takes_every_shapes_pool(self):
        cells = {"disk": [[0.0, 0.1]], "square": [[0.3, 0.5]], "triangle": [[-0.2]], "rect_wide": []}
        scatter = findings.shape_scatter(cells)
        pooled = math.sqrt((0.005 + 0.02) / 2)
        for shape in ("triangle", "rect_wide"):
            self.assertAlmostEqual(scatter[shape].sigma, pooled)
            self.assertEqual((scatter[shape].dof, scatter[shape].cells, scatter[shape].own), (2, 2, False))
        self.assertTrue(scatter["disk"].own)
        self.assertAlmostEqual(scatter["disk"].sigma, 0.1 / math.sqrt(2))

    def test_no_degrees_of_freedom_no_sigma(self):
        sigma, dof, cells = findings.pooled_scatter([[0.1], [0.2]])
        self.assertTrue(math.isnan(sigma))
        self.assertEqual((dof, cells), (0, 0))
        scatter = findings.shape_scatter({"disk": [[0.1]], "square": []})
        self.assertTrue(all(math.isnan(s.sigma) and s.dof == 0 and not s.own for s in scatter.values()))

    def test_students_t_for_few_degrees_of_freedom(self):
        for dof, t in ((1, 12.706), (2, 4.303), (3, 3.182), (4, 2.776), (5, 2.571), (10, 2.228), (30, 2.042)):
            self.assertAlmostEqual(findings.t_critical(dof), t, places=3)
        self.assertAlmostEqual(findings.t_critical(100000), 1.960, places=3)
        self.assertEqual(findings.t_critical(0), math.inf)
        self.assertAlmostEqual(findings.t_critical(5, level=0.90), 2.015, places=3)


class SignCrossingTest(unittest.TestCase):
    """Where the mean turns positive (the paper's reading) against the paper's range."""

    def test_at_or_below_inside_and_above(self):
        paper = (3.0, 4.0)
        self.assertEqual(findings.crossing_against_range(2.5, 3.0, paper), -1)
        self.assertEqual(findings.crossing_against_range(2.0, 2.5, paper), -1)
        self.assertEqual(findings.crossing_against_range(3.0, 4.0, paper), 0)
        self.assertEqual(findings.crossing_against_range(3.5, 5.0, paper), 0)
        self.assertEqual(findings.crossing_against_range(4.0, 5.0, paper), +1)

    def test_what_the_periods_run_cannot_place(self):
        paper = (2.0, 3.0)
        # positive already at 2.5, its shortest run: below 2 or inside 2-3, the runs do not say
        self.assertIsNone(findings.crossing_against_range(None, 2.5, paper))
        # positive already at 2: at or below the lower end whatever lies below
        self.assertEqual(findings.crossing_against_range(None, 2.0, paper), -1)
        # never positive up to 8, past the upper end: above the range; up to 2.5 only: not placed
        self.assertEqual(findings.crossing_against_range(8.0, None, paper), +1)
        self.assertIsNone(findings.crossing_against_range(2.5, None, paper))


class VerdictWordsTest(unittest.TestCase):
    """The verdict beside the counts that decide it, so that a verdict of many 'for' reads as its rule."""

    def test_one_against_is_named_as_what_decides(self):
        outcomes = ["for"] * 12 + ["within"] * 6 + ["against"] * 2
        self.assertEqual(findings.verdict_words(outcomes), "not reproduced: 2 of 20 against (12 for, 6 within)")

    def test_reproduced_and_not_resolved(self):
        self.assertEqual(findings.verdict_words(["for"] * 4), "reproduced: all 4 for")
        self.assertEqual(findings.verdict_words(["for"] * 5 + ["within"] * 3),
                         "not resolved: none against, 3 of 8 within (5 for)")
        self.assertEqual(findings.verdict_words([]), "not measured")


class CellSideTest(unittest.TestCase):
    """A cell's side of zero by the rule, and whether it says what the paper's Table 1 says."""

    def test_side_of_zero_at_two_standard_errors(self):
        self.assertEqual(findings.cell_side([0.1], SIGMA), +1)       # 2.0 se
        self.assertEqual(findings.cell_side([-0.1], SIGMA), -1)
        self.assertEqual(findings.cell_side([0.09], SIGMA), 0)       # 1.8 se: level within the scatter

    def test_not_rising_is_the_papers_side_below_its_range_whether_level_or_sinking(self):
        self.assertTrue(findings.on_paper_side([-0.001], 0.01, -1))
        self.assertTrue(findings.on_paper_side([-0.05], 0.01, -1))
        self.assertFalse(findings.on_paper_side([0.05], 0.01, -1))

    def test_rising_is_the_papers_side_above_its_range_and_level_is_not(self):
        self.assertTrue(findings.on_paper_side([0.05], 0.01, +1))
        self.assertFalse(findings.on_paper_side([-0.001], 0.01, +1))


class OwnScatterTest(unittest.TestCase):
    """A change resolved on sigma whose side of 2 beds scatters more than sigma (own_scatter_judged)."""

    BASE = [-0.047, -0.039]

    def test_resolved_on_sigma_not_by_its_own_beds_larger_scatter(self):
        # 0.0205 is 2.6 se on sigma 0.008 (2 beds a side); the row's 2 beds scatter by 0.019: 1.1 se by that
        scattered = compare("t", [-0.036, -0.009], self.BASE, +1)
        z = judged(scattered, 0.008)[1]
        self.assertEqual(z, 2.6)
        side, n, own, z_own = findings.own_scatter_judged(scattered, z, 0.008)
        self.assertEqual((side, n, z_own), ("a", 2, 1.1))
        self.assertAlmostEqual(own, findings.sd([-0.036, -0.009]))

    def test_beds_that_agree_leave_the_change_as_it_stands(self):
        agreeing = compare("t", [-0.022, -0.023], self.BASE, +1)
        self.assertIsNone(findings.own_scatter_judged(agreeing, judged(agreeing, 0.008)[1], 0.008))

    def test_the_compared_sides_scatter_counts_too(self):
        loose_base = compare("t", [-0.022, -0.023], [-0.060, -0.026], +1)
        z = judged(loose_base, 0.008)[1]
        self.assertEqual(findings.own_scatter_judged(loose_base, z, 0.008)[:2], ("b", 2))

    def test_a_change_within_the_scatter_needs_no_second_look(self):
        within = compare("t", [-0.036, -0.009], [-0.030, -0.029], +1)
        self.assertEqual(judged(within, 0.008)[2], "within")
        self.assertIsNone(findings.own_scatter_judged(within, judged(within, 0.008)[1], 0.008))

    def test_three_beds_are_counted_by_judged_itself(self):
        three = compare("t", [-0.036, -0.009, -0.020], self.BASE, +1)
        self.assertIsNone(findings.own_scatter_judged(three, 2.6, 0.008))


class ChangeInStandardErrorsTest(unittest.TestCase):
    def test_a_paired_change_in_standard_errors_of_the_pooled_deviation(self):
        self.assertAlmostEqual(findings.change_z([0.1, 0.1], 0.05), 0.1 / (0.05 / math.sqrt(2)))
        self.assertAlmostEqual(findings.change_z([-0.03], 0.01), -3.0)

    def test_resolved_by_the_rule_yet_short_of_students_t(self):
        # 2 dof: Student's 95 % is 4.30 se; 3.0 se passes the rule of 2 and falls short of it
        self.assertAlmostEqual(findings.below_student(3.0, 2), findings.t_critical(2))
        self.assertAlmostEqual(findings.below_student(-3.0, 2), findings.t_critical(2))
        self.assertIsNone(findings.below_student(1.9, 2))      # not resolved by the rule at all
        self.assertIsNone(findings.below_student(5.0, 2))      # holds by Student's t too
        self.assertIsNone(findings.below_student(3.0, 30))     # 2.04 for 30 dof: holds


class RunShapeTest(unittest.TestCase):
    """A run's slope and its phase profile's harmonics."""

    def test_least_squares_slope_of_a_line_and_of_a_scatter_about_it(self):
        ts = [0.0, 1.0, 2.0, 3.0]
        self.assertAlmostEqual(findings.least_squares_slope(ts, [1.0 + 0.5 * t for t in ts]), 0.5)
        self.assertAlmostEqual(findings.least_squares_slope(ts, [0.0, 1.0, 1.0, 2.0]), 0.6)

    def test_harmonics_give_back_a_made_up_profile(self):
        # 0.05 + 0.2 cos(2 (phi - 3.3 pi / 10)) + 0.1 cos(phi - 1) over 20 bins
        centres = [k + 0.5 for k in range(20)]
        bins = [0.05 + 0.2 * math.cos(2 * (c * math.pi / 10 - 3.3 * math.pi / 10)) + 0.1 * math.cos(c * math.pi / 10 - 1)
                for c in centres]
        h = findings.phase_harmonics(centres, bins)
        for got, want in zip(h, (0.05, 0.1, 0.2, 3.3, 0.0)):
            self.assertAlmostEqual(got, want, places=12)

    def test_what_the_first_two_harmonics_leave_is_the_rest(self):
        # a third harmonic of 0.03 alone: its rms per bin is 0.03 / sqrt(2)
        centres = [k + 0.5 for k in range(20)]
        h = findings.phase_harmonics(centres, [0.03 * math.cos(3 * c * math.pi / 10) for c in centres])
        self.assertAlmostEqual(h.whole, 0.0, places=12)
        self.assertAlmostEqual(h.half, 0.0, places=12)
        self.assertAlmostEqual(h.rest, 0.03 / math.sqrt(2), places=12)


if __name__ == "__main__":
    unittest.main()
