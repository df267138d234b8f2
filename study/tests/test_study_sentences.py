"""The words study/tools's blocks pick from numbers (study/tools/vy_tables.py and its modules), on
small made-up cells: which way a rate or a change goes, whether a factor moved a cell, what is left
unexplained, how a bracket stands against the paper. The statistics behind them are findings.py's
(test_findings.py); here only the choice of words. One bed's sigma given, as there."""
import math
import os
import shutil
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import answer_sentences  # noqa: E402
import cases  # noqa: E402
import factor_tables  # noqa: E402
import findings  # noqa: E402
import findings_table  # noqa: E402
import scatter  # noqa: E402
import table1_blocks  # noqa: E402
import table_kinds  # noqa: E402

SIGMA = 0.01   # one bed's standard deviation of these made-up cells
compare = findings.compare


class MadeUpCase:
    """A stand-in case whose trajectory.csv has y at the given times."""

    source, row = "made-up", {"case": "made_up"}

    def __init__(self, ys):
        self.ys = ys

    def trajectory(self):
        return sorted(self.ys), [self.ys[t] for t in sorted(self.ys)]


def climbing(first, second):
    """A case whose rate by the paper's rule is `first` over t = 100-500 and `second` over 500-1000."""
    return MadeUpCase({100.0: 0.0, 500.0: 400 * first, 1000.0: 400 * first + 500 * second})


class TurningExtentTest(unittest.TestCase):
    """How far a turning body turned, from its trajectory.csv's angle column."""

    def case(self, rows, header="t,x,y,vx,vy,fy,angle,omega"):
        folder = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, folder)
        with open(os.path.join(folder, "trajectory.csv"), "w") as f:
            f.write(header + "\n" + "".join(r + "\n" for r in rows))
        return cases.Case("made-up", {"case": "made_up"}, folder)

    def test_the_largest_turn_counts_only_inside_the_papers_window(self):
        # 0.5 rad before t = 100 is left out; -0.2 is the largest turn inside; 0.1 the last
        turned = self.case(["0,0,90,0,0,0,0,0", "50,0,90,0,0,0,0.5,0", "100,0,90,0,0,0,0.05,0",
                            "500,0,90,0,0,0,-0.2,0", "1000,0,90,0,0,0,0.1,0"])
        most, end = factor_tables.turning_extent(turned)
        self.assertAlmostEqual(most, math.degrees(0.2))
        self.assertAlmostEqual(end, math.degrees(0.1))

    def test_the_rise_splits_by_how_the_body_stood(self):
        # a triangle: apex up (0 deg) from t = 100 to 300, rising 2 d; then turned 60 deg (apex down) from 300
        # to 500, rising 40 d; then 125 deg (5 past a whole repeat: as started) to 1000, sinking 5 d;
        # before t = 100 (left out) it stood apex down
        rad = math.radians
        turned = self.case([f"0,0,90,0,0,0,{rad(60)},0", f"100,0,90,0,0,0,0,0", f"300,0,92,0,0,0,{rad(60)},0",
                            f"500,0,132,0,0,0,{rad(125)},0", f"1000,0,127,0,0,0,{rad(125)},0"])
        (half, rate_half), (started, rate_started) = factor_tables.orientation_rates(turned, "triangle")
        self.assertEqual((half, started), (200.0, 700.0))
        self.assertAlmostEqual(rate_half, 40.0 / 200.0)
        self.assertAlmostEqual(rate_started, -3.0 / 700.0)
        self.assertEqual(factor_tables.orientation_words(turned, "triangle", 5.0),
                         "apex down for 200 of the window's 900 (first for a whole period from t = 0), at +0.200; as started at -0.004")
        # 200 is under 10 periods of T = 25: no rate for so short a time
        self.assertEqual(factor_tables.orientation_words(turned, "triangle", 25.0),
                         "apex down for 200 of the window's 900 (first for a whole period from t = 0); as started at -0.004")
        # when it first held half-turned for a whole period, counted from t = 0, before the window too: a
        # swing of less than a period half-turned (t = 100-102 at T = 5) is a rock, not a turn
        later = self.case(["0,0,90,0,0,0,0,0", f"100,0,90,0,0,0,{rad(40)},0", f"102,0,90,0,0,0,{rad(10)},0",
                           f"650,0,90,0,0,0,{rad(-50)},0", f"653,0,90,0,0,0,{rad(-70)},0", f"655,0,90,0,0,0,{rad(-60)},0"])
        self.assertEqual(factor_tables.first_half_turned(later, "triangle", 5.0), 650.0)
        self.assertIsNone(factor_tables.first_half_turned(later, "triangle", 6.0))
        # a square a quarter turn round (90 deg) stands as it started; 45 deg is on a corner
        self.assertEqual(factor_tables.orientation_rates(self.case(["100,0,90,0,0,0,%r,0" % rad(90),
                                                                   "200,0,91,0,0,0,0,0"]), "square")[0], (0.0, None))

    def test_a_body_that_does_not_turn_has_no_angle_to_read(self):
        locked = self.case(["0,0,90,0,0,0", "1000,0,90,0,0,0"], header="t,x,y,vx,vy,fy")
        with self.assertRaisesRegex(ValueError, "records no angle"):
            locked.turn()


class ScatterCasesTest(unittest.TestCase):
    """Which coupling cases count in the clock's scatter: its new pours of a locked body only."""

    def test_only_the_coupling_screens_new_pours_of_a_locked_body_count(self):
        class Ran:   # a made-up case: its name, whether it poured its own bed, its coupling keys
            def __init__(self, name, own, **keys):
                self.row, self.own = {"case": name}, own
                self.keys = dict(scatter.LOCKED_BODY, **{k.replace("__", "."): v for k, v in keys.items()})

            def get(self, key):
                return self.keys[key]

            def pours_own_bed(self):
                return self.own

        made_up = [Ran("baseline_s4", True), Ran("atom", False, intruder__contact_mass="atom"),
                   Ran("free_s4", True, intruder__rotation="free"), Ran("velocity_s4", True, drive__form="velocity"),
                   Ran("swapped", False)]
        real = scatter.load
        scatter.load = lambda source: made_up
        try:
            self.assertEqual([c.row["case"] for c in scatter.scatter_cases(scatter.COUPLING[0])], ["baseline_s4"])
            self.assertEqual(len(scatter.scatter_cases("results/paper_depth/factors_t1000")), len(made_up))
        finally:
            scatter.load = real


class CellTextTest(unittest.TestCase):
    def test_beds_counted_with_their_noun(self):
        self.assertEqual(cases.beds_count([1]), "1 bed")
        self.assertEqual(cases.beds_count([2, 2]), "2 beds")
        self.assertEqual(cases.beds_count(n for n in (2, 1, 3)), "1-3 beds")
        self.assertEqual(cases.count_range([]), "0")

    def test_a_cell_of_one_bed_and_of_several(self):
        self.assertEqual(cases.cell_text([0.054]), "+0.054 (1 bed)")
        self.assertEqual(cases.cell_text([0.03, 0.05], each=True), "+0.040 +- 0.010 (2 beds: +0.030, +0.050)")
        self.assertEqual(cases.beds_text([0.017, 0.021]), "+0.019 (2 beds)")


class AmplitudeThresholdTest(unittest.TestCase):
    """The smallest amplitude at which V_y leaves zero, either way (table_kinds.threshold_text)."""

    def test_the_bracket_from_the_amplitude_below_and_the_way_it_goes(self):
        measured = [(0.5, [0.001]), (1.0, [0.005]), (3.0, [0.05])]
        self.assertEqual(table_kinds.threshold_text(measured, SIGMA), "1-3 (rises)")
        self.assertEqual(table_kinds.threshold_text([(0.5, [-0.03]), (1.0, [-0.05])], SIGMA), "<= 0.5 (sinks)")

    def test_none_resolved_is_above_the_largest_measured(self):
        self.assertEqual(table_kinds.threshold_text([(0.5, [0.001]), (1.0, [-0.019])], SIGMA), "above 1")
        self.assertEqual(table_kinds.threshold_text([], SIGMA), "")


class PaperReadingTest(unittest.TestCase):
    """A cell read against the paper's Table 1 at its period (scatter.reading_words)."""

    def test_below_the_papers_range_level_or_sinking_is_as_the_paper(self):
        self.assertEqual(scatter.reading_words([-0.001], SIGMA, -1), "not rising, as the paper")
        self.assertEqual(scatter.reading_words([-0.05], SIGMA, -1), "not rising, as the paper")
        self.assertEqual(scatter.reading_words([0.05], SIGMA, -1), "rising, where the paper has it not rising")

    def test_above_it_only_rising_is(self):
        self.assertEqual(scatter.reading_words([0.05], SIGMA, +1), "rising, as the paper")
        self.assertEqual(scatter.reading_words([0.015], SIGMA, +1), "not rising, where the paper has it rising")

    def test_inside_it_the_cells_own_side(self):
        self.assertEqual(scatter.reading_words([0.001], SIGMA, 0), "level within the scatter, inside the paper's range")
        self.assertEqual(scatter.reading_words([-0.05], SIGMA, 0), "sinking, inside the paper's range")


class BracketTextTest(unittest.TestCase):
    """Wiggle's bracket and the sign crossing, as the Table 1 blocks print them."""

    def test_bracket(self):
        cells = [(2.0, [-0.1]), (2.5, [0.0]), (3.0, [0.1])]
        self.assertEqual(table1_blocks.bracket_text(2.5, 3.0, cells), "2.5-3")
        self.assertEqual(table1_blocks.bracket_text(None, 2.0, cells), "<= 2")
        self.assertEqual(table1_blocks.bracket_text(None, None, cells), "none: not rising at T = 2-3")
        self.assertEqual(table1_blocks.bracket_text(None, None, cells[:1]), "none: not rising at T = 2")
        self.assertEqual(table1_blocks.bracket_text(None, None, []), "not run")

    def test_where_the_mean_turns_positive(self):
        self.assertEqual(table1_blocks.sign_crossing([(2.0, [-0.1]), (2.5, [0.01, -0.02]), (3.0, [0.1])]), (2.5, 3.0))
        self.assertEqual(table1_blocks.sign_crossing([(2.0, [0.1]), (3.0, [0.2])]), (None, 2.0))
        self.assertEqual(table1_blocks.sign_crossing([(2.0, [-0.1]), (3.0, [-0.2])]), (3.0, None))
        cells = [(2.0, [-0.1]), (3.0, [-0.2])]
        self.assertEqual(table1_blocks.crossing_text(3.0, None, cells), "none: mean <= 0 up to T = 3")
        self.assertEqual(table1_blocks.crossing_text(None, 2.0, cells), "> 0 already at T = 2, the shortest run")


class FindingsWordsTest(unittest.TestCase):
    """A finding's comparisons at one scale in study/FINDINGS.md's table and on the answer page."""

    COMPARISONS = [compare("sinks", [-0.1], None, -1), compare("rises", [-0.1, -0.12], None, +1), None]

    def test_counts_and_each_against_named(self):
        self.assertEqual(findings_table.comparisons_text(0.05, self.COMPARISONS, []),
                         "2 comparisons of cases of 1-2 beds: 1 the paper's way by >= 2 standard errors, "
                         "0 within 2, 1 against: rises (-3.1)")
        self.assertEqual(findings_table.comparisons_text(0.05, self.COMPARISONS[:1], ["one shape"]),
                         "1 comparison of cases of 1 bed: 1 the paper's way by >= 2 standard errors, "
                         "0 within 2, 0 against (one shape)")

    def test_no_comparison_says_why_or_that_nothing_is_committed(self):
        self.assertEqual(findings_table.comparisons_text(0.05, [None], ["not judged: why"]), "not judged: why")
        self.assertEqual(findings_table.comparisons_text(0.05, [], []), "no committed results")

    def test_the_answer_pages_verdict_reads_as_its_rule(self):
        self.assertEqual(findings_table.verdict_cell(0.05, self.COMPARISONS, []),
                         "**not reproduced**: 1 of 2 against (1 for, 0 within) (1-2 beds)")
        self.assertEqual(findings_table.verdict_cell(0.05, self.COMPARISONS[:1], []), "**reproduced**: all 1 for (1 bed)")
        self.assertEqual(findings_table.verdict_cell(0.05, [], ["why"]), "not judged")


class ChangeWordsTest(unittest.TestCase):
    """Which way a factor's change moves a cell (factor_tables)."""

    BASE = [-0.047, -0.039]

    def test_toward_away_or_within_by_two_standard_errors_the_papers_way(self):
        self.assertEqual(factor_tables.toward_words(2.0), "toward the paper")
        self.assertEqual(factor_tables.toward_words(-2.6), "away from the paper")
        self.assertEqual(factor_tables.toward_words(1.9), "within the scatter")
        self.assertEqual(factor_tables.toward_words(5.0, "1.1 se by its 2 beds' own scatter"), "within the scatter")

    def test_a_change_resolved_on_sigma_but_not_by_its_own_beds_is_shown_within_the_scatter(self):
        diff, z, toward, caveat = factor_tables.judged_change(compare("t", [-0.036, -0.009], self.BASE, +1), 0.008)
        self.assertAlmostEqual(diff, 0.0205)
        self.assertEqual((z, toward), (2.6, "within the scatter"))
        self.assertEqual(caveat, "1.1 se by its 2 beds' own scatter, one bed's standard deviation 0.0191 "
                                 "against sigma 0.0080")

    def test_beds_that_agree_leave_it_toward_the_paper(self):
        change = factor_tables.judged_change(compare("t", [-0.022, -0.023], self.BASE, +1), 0.008)
        self.assertEqual(change[1:], (2.6, "toward the paper", ""))
        self.assertEqual(factor_tables.change_text(change), "+0.0205 (2.6 se, toward the paper)")

    def test_the_compared_rows_beds_are_named_when_theirs_scatter(self):
        comparison = compare("t", [-0.022, -0.023], [-0.060, -0.026], +1)
        caveat = factor_tables.judged_change(comparison, 0.008)[3]
        self.assertTrue(caveat.startswith("0.9 se by the compared row's 2 beds' own scatter"), caveat)

    def test_a_change_away_from_the_paper(self):
        change = factor_tables.judged_change(compare("t", [-0.07, -0.07], self.BASE, +1), 0.008)
        self.assertEqual(factor_tables.change_text(change), "-0.0270 (3.4 se, away from the paper)")

    def test_where_a_period_stands_in_the_papers_range(self):
        self.assertEqual([factor_tables.range_end(t, (3.0, 4.0)) for t in (3.0, 4.0, 5.0)],
                         ["the lower end of", "the upper end of", "beside"])


class CourseWordsTest(unittest.TestCase):
    """How a rate holds through the paper's window, by its halves (answer_sentences)."""

    def test_stalls_turns_back_faster_slower(self):
        self.assertEqual(answer_sentences.course_words(0.070, 0.008), "then stalls")
        self.assertEqual(answer_sentences.course_words(0.05, -0.03), "then turns back")
        self.assertEqual(answer_sentences.course_words(-0.026, -0.056), "then faster")
        self.assertEqual(answer_sentences.course_words(0.05, 0.03), "then slower")
        # a quarter of the first half's rate is not yet a stall
        self.assertEqual(answer_sentences.course_words(0.04, 0.01), "then slower")

    def test_periods_that_go_alike_share_a_clause(self):
        by_t = {3.0: [climbing(0.070, 0.008)], 4.0: [climbing(0.114, 0.004)], 5.0: [climbing(-0.02, -0.03)]}
        self.assertEqual(answer_sentences.courses_text("square", by_t),
                         ["the square climbs over t = 100-500 (+0.070 at T = 3, +0.114 at T = 4), then stalls over "
                          "t = 500-1000 (+0.008, +0.004)",
                          "the square sinks over t = 100-500 (-0.020 at T = 5), then faster over t = 500-1000 (-0.030)"])
        self.assertEqual(len(answer_sentences.courses_text("square", by_t, ("then stalls", "then turns back"))), 1)


class CrossingsSentenceTest(unittest.TestCase):
    """Where the sign crossings lie against the paper's ranges, in a sentence."""

    def crossing(self, shape, lo, hi, cells):
        return (shape, lo, hi, findings.crossing_against_range(lo, hi, cases.PAPER_RANGE[shape]), cells)

    def test_every_crossing_at_or_below_the_papers_lower_end_is_a_shift(self):
        found = [self.crossing("disk", 2.0, 2.5, []), self.crossing("square", 2.5, 3.0, [])]
        said = answer_sentences.crossings_sentence(found)
        self.assertEqual(said, f"every crossing the runs place lies at or below the paper's lower end (disk 2-2.5 against "
                               f"{cases.paper_observed('disk')}, square 2.5-3 against {cases.paper_observed('square')}): "
                               "a shift to shorter periods")

    def test_otherwise_each_placed_crossing_with_its_words_and_the_rest_after(self):
        lo, hi = cases.PAPER_RANGE["square"]
        found = [self.crossing("disk", 2.0, 2.5, []), self.crossing("square", hi, hi + 1, []),
                 self.crossing("triangle", 5.0, None, [(3.0, [-0.1]), (5.0, [-0.1])])]
        said = answer_sentences.crossings_sentence(found)
        self.assertTrue(said.startswith(f"the crossings the runs place: disk 2-2.5, at or below the paper's lower end; "
                                        f"square {hi:g}-{hi + 1:g}, above the paper's range; "), said)
        self.assertTrue(said.endswith(f"the triangle's mean stays <= 0 up to T = 5 (paper: "
                                      f"{cases.paper_observed('triangle')})"), said)
        self.assertNotIn("triangle", answer_sentences.crossings_sentence(found, rest_too=False))


class ReadmeWordsTest(unittest.TestCase):
    """The README's paragraph: which list a shape's bracket goes in, and what the factors moved."""

    def test_bracket_kinds(self):
        paper = (3.0, 4.0)
        self.assertEqual(answer_sentences.bracket_kind(3.0, 4.0, paper), "agrees")
        self.assertEqual(answer_sentences.bracket_kind(3.0, 3.5, paper), "agrees")
        self.assertEqual(answer_sentences.bracket_kind(None, None, paper), "never rises")
        self.assertEqual(answer_sentences.bracket_kind(2.5, 3.0, paper), "differs")
        self.assertEqual(answer_sentences.bracket_kind(None, 3.0, paper), "differs")
        self.assertEqual(answer_sentences.bracket_kind(None, 3.5, paper), "not placed")

    def test_what_the_factors_moved(self):
        moved = ["the random pour moves the square at T = 3 toward the paper (2.4 se)"]
        self.assertEqual(answer_sentences.moved_text(moved, []), moved[0])
        self.assertEqual(answer_sentences.moved_text([], []), "none moves a cell by 2 standard errors")
        self.assertEqual(answer_sentences.moved_text([], ["x by 2.6 se of sigma, why"]),
                         "none moves a cell by 2 standard errors of the scatter its own runs show (x by 2.6 se of sigma, why)")
        self.assertEqual(answer_sentences.moved_text(moved, ["x by 4.2 se of sigma, why"]),
                         moved[0] + "; not by the scatter its own runs show, x by 4.2 se of sigma, why")


class VelocitySentenceTest(unittest.TestCase):
    """Whether one bed a cell tells where the velocity reading crosses (answer_sentences)."""

    def test_none_resolved_says_one_bed_does_not_tell(self):
        said = answer_sentences.velocity_sentence({"disk": [(2.5, [0.001]), (3.0, [-0.015])], "square": []}, SIGMA)
        self.assertTrue(said.startswith("At A = 5, read as a velocity, the disk gives +0.001, -0.015 at T = 2.5, 3 "
                                        "(1 bed each: +0.1, -1.5 se), in standard errors"), said)
        self.assertTrue(said.endswith("none is 2 se from zero, so one bed each does not tell whether, or where, "
                                      "either crosses over the periods run."), said)

    def test_one_resolved_either_way_is_shown_by_the_table(self):
        said = answer_sentences.velocity_sentence({"disk": [(2.5, [0.001])], "square": [(3.0, [-0.02, -0.03])]}, SIGMA)
        self.assertIn("the square gives -0.025 at T = 3 (2 beds each: -3.5 se)", said)
        self.assertTrue(said.endswith("some are 2 se or more from zero, as the table above shows."), said)

    def test_nothing_run_says_nothing(self):
        self.assertEqual(answer_sentences.velocity_sentence({"disk": [], "square": []}, SIGMA), "")


class WhatIsLeftTest(unittest.TestCase):
    """What the factors measured in a cell account for, and what is left (answer_sentences)."""

    TOWARD = ("the random pour", (0.02, 2.4, "toward the paper", ""))
    WITHIN = ("the glued surface", (0.01, 1.2, "within the scatter", ""))
    DOUBTED = ("the glued mass", (0.02, 2.6, "within the scatter", "1.1 se by its 2 beds' own scatter"))

    def test_resolved_changes_are_named_with_their_way(self):
        self.assertEqual(answer_sentences.what_moved([self.TOWARD, self.WITHIN]),
                         "Resolved by 2 standard errors: the random pour, toward the paper. ")

    def test_none_resolved_and_whether_by_its_own_beds_scatter(self):
        self.assertEqual(answer_sentences.what_moved([self.WITHIN]), "No measured factor moves it by 2 standard errors. ")
        self.assertEqual(answer_sentences.what_moved([self.WITHIN, self.DOUBTED]),
                         "No measured factor moves it by 2 standard errors of the scatter its own runs show. ")
        self.assertEqual(answer_sentences.what_moved([]), "")

    def test_on_the_papers_side_there_is_nothing_to_account_for(self):
        self.assertEqual(answer_sentences.what_is_left([self.WITHIN], True, ""),
                         "In the paper's box by its protocol the cell is on the paper's side.")

    def test_none_toward_the_paper_leaves_all_of_it_some_leaves_the_rest(self):
        self.assertEqual(answer_sentences.what_is_left([self.WITHIN], False, "the coupling"),
                         "So none of the difference is accounted for: what is left is all of it: the coupling.")
        self.assertEqual(answer_sentences.what_is_left([self.TOWARD, self.WITHIN], False, "the coupling"),
                         "So not all of the difference is accounted for: what is left is the rest: the coupling.")

    def test_a_coupling_factor_toward_the_paper_is_named_with_where_it_has_run(self):
        lattice = factor_tables.CouplingChange(0.11, 10.2, "toward the paper", "the lattice body", "the triangle at T = 5", 2)
        self.assertEqual(answer_sentences.what_is_left([self.WITHIN], False, "the rest", [(lattice, None)]),
                         "So the protocol's factors account for none of the difference; the intruder's coupling may: "
                         "the lattice body moves it +0.1100 (10.2 se, toward the paper; 2 beds paired) in the 60 d box; "
                         "in the paper's box: not run yet. Left beside it: the rest.")
        # the screen's other factors at the cell follow, measured or not
        atom = factor_tables.CouplingChange(0.0059, 0.5, "within the scatter", "the atoms' mass", "the triangle at T = 5", 2)
        self.assertIn("in the paper's box: not run yet. The screen's other factors at this cell: the atoms' mass +0.0059 "
                      "(0.5 se, within the scatter; 2 beds paired); not run here yet: turning. Left beside it: the rest.",
                      answer_sentences.what_is_left([self.WITHIN], False, "the rest", [(lattice, None)],
                                                    [("the atoms' mass", atom), ("turning", None)]))
        self.assertIn("not run yet. Not run here yet: turning. Left",
                      answer_sentences.what_is_left([self.WITHIN], False, "the rest", [(lattice, None)], [("turning", None)]))
        reading = factor_tables.PaperBoxReading
        # finished: judged as a cell (its side by the rule, against the paper's) and as a change of one bed a side
        sig = scatter.clock_sigma("triangle")
        vy, base = 5.0 * sig, -4.0 * sig
        z_vy, z_change = round(vy / sig, 1), round((vy - base) / (sig * 2 ** 0.5), 1)
        self.assertEqual(answer_sentences.what_is_left([self.TOWARD], False, "the rest",
                                                       [(lattice, reading("triangle", 5.0, vy, base))]),
                         "So the protocol's factors account for not all of the difference; the intruder's coupling may: "
                         "the lattice body moves it +0.1100 (10.2 se, toward the paper; 2 beds paired) in the 60 d box; "
                         f"in the paper's box: V_y {vy:+.3f} (1 bed, {z_vy:+.1f} se), rising, as the paper; against the "
                         f"protocol's {base:+.4f} on the same bed, {vy - base:+.4f} ({z_change:.1f} se, toward the paper). "
                         "Left beside it: the rest.")
        # a small rise on one bed is not judged rising, and a small change is within the scatter
        small = answer_sentences.what_is_left([self.TOWARD], False, "", [(lattice, reading("triangle", 5.0, 0.5 * sig, 0.0))])
        self.assertIn("(1 bed, +0.5 se), not rising, where the paper has it rising; against", small)
        self.assertIn("(0.4 se, within the scatter)", small)
        # a case carried part-way: where it has got, then its rate so far once the window is long enough
        self.assertIn("in the paper's box: being run (t = 150 of 1000 committed). Left",
                      answer_sentences.what_is_left([self.WITHIN], False, "the rest", [(lattice, reading("triangle", 5.0, None, None, 150.0, 1000.0))]))
        self.assertIn("in the paper's box: being run, so far (t = 100-315, not judged) +0.0300 against the protocol's "
                      "-0.0250 on the same bed over the same window (one bed). Left",
                      answer_sentences.what_is_left([self.WITHIN], False, "the rest", [(lattice, reading("triangle", 5.0, 0.03, -0.025, 315.0, 1000.0))]))
        # on the paper's side there is nothing to account for, whatever the coupling does
        self.assertEqual(answer_sentences.what_is_left([self.WITHIN], True, "", [(lattice, None)]),
                         "In the paper's box by its protocol the cell is on the paper's side.")

    def test_the_coupling_screen_so_far(self):
        within = factor_tables.CouplingChange(0.001, 0.5, "within the scatter", "the lattice body", "the square at T = 3", 2)
        moved = factor_tables.CouplingChange(0.02, 3.0, "toward the paper", "turning", "the triangle at T = 5", 1)
        self.assertEqual(answer_sentences.coupling_status([(within, None, ""), (None, None, "")]),
                         "its screen being run, 1 change measured so far, on 2 beds each: none moves a cell by 2 "
                         "standard errors so far; study/VALIDATION.md, \"The intruder's coupling\"")
        self.assertEqual(answer_sentences.coupling_status([(within, None, ""), (moved, None, "")]),
                         "its screen being run, 2 changes measured so far, on 1-2 beds each: turning moves the "
                         "triangle at T = 5 toward the paper (+0.020, 3.0 se, in the 60 d box; not run in the paper's "
                         "box yet); study/VALIDATION.md, \"The intruder's coupling\"")
        # the screen run: nothing is "so far"
        self.assertEqual(answer_sentences.coupling_status([(within, None, "")], True),
                         "its screen run, 1 change measured, on 2 beds each: none moves a cell by 2 standard errors; "
                         "study/VALIDATION.md, \"The intruder's coupling\"")
        # a move away from the paper is not one the paper's box is run for: nothing said of it there
        away = factor_tables.CouplingChange(0.013, 5.3, "away from the paper", "turning", "the square at T = 3", 2)
        self.assertIn("each: turning moves the square at T = 3 away from the paper (+0.013, 5.3 se, in the 60 d box); "
                      "study/VALIDATION.md", answer_sentences.coupling_status([(away, None, "")]))
        # resolved on sigma, not by the scatter the shape's paired runs show: said so, after the moves
        split = factor_tables.CouplingChange(0.074, 6.8, "within the scatter", "turning", "the triangle at T = 5", 2,
                                             ", 1.7 se by the scatter the triangle's paired runs show")
        self.assertIn("each: turning moves the square at T = 3 away from the paper (+0.013, 5.3 se, in the 60 d box); "
                      "turning moves the triangle at T = 5 by 6.8 se of sigma (+0.074) but 1.7 se by the scatter the "
                      "triangle's paired runs show: not resolved; study/VALIDATION.md",
                      answer_sentences.coupling_status([(away, None, ""), (split, None, "")]))
        # a factor's name carries its own article: it is not doubled
        lattice = factor_tables.CouplingChange(0.11, 7.1, "toward the paper", "the lattice body", "the triangle at T = 5", 1)
        self.assertIn("each: the lattice body moves the triangle at T = 5 toward the paper (+0.110, 7.1 se",
                      answer_sentences.coupling_status([(lattice, None, "")]))
        # where the paper's box has run it: how it reads there, by the rule, against the paper
        reading = factor_tables.PaperBoxReading
        sig = scatter.clock_sigma("triangle")
        self.assertIn(f"in the 60 d box; in the paper's box {5 * sig:+.3f} (1 bed, +5.0 se): rising, as the paper)",
                      answer_sentences.coupling_status([(lattice, reading("triangle", 5.0, 5 * sig, -sig), "")]))
        self.assertIn("in the 60 d box; being run in the paper's box)",
                      answer_sentences.coupling_status([(lattice, reading("triangle", 5.0, None, None, 150.0, 1000.0), "")]))

    def test_a_change_is_not_resolved_beyond_its_shapes_paired_runs(self):
        # made-up: the square's paired changes stray (one bed's sd of a change 0.0200, 2 dof); the triangle's do not
        found = {"square": [("square", 0.0200, 2, 0.0034)], "triangle": []}
        real, factor_tables.straying = factor_tables.straying, lambda shapes: found[shapes[0]]
        try:
            sig = 0.0024
            run_sd = 0.0200 / 2 ** 0.5
            # +0.0125 against one bed: 3.7 se of sigma, under 2 by one run's sd: shown within the scatter
            change = factor_tables.judged_change(findings.Comparison("square", [0.0125], [0.0], 1), sig)
            self.assertEqual(change[2], "within the scatter")
            z_run = round(0.0125 / (run_sd * 2 ** 0.5), 1)
            self.assertEqual(change[3], f"{z_run:.1f} se by the scatter the square's paired runs show, one run's "
                                        f"standard deviation {run_sd:.4f} (2 dof) against sigma 0.0024")
            # resolved by both: no caveat; the triangle's runs do not stray: sigma alone judges
            self.assertEqual(factor_tables.judged_change(findings.Comparison("square", [0.1], [0.0], 1), sig)[2:],
                             ("toward the paper", ""))
            self.assertEqual(factor_tables.judged_change(findings.Comparison("triangle", [0.0125], [0.0], 1), sig)[2:],
                             ("toward the paper", ""))
        finally:
            factor_tables.straying = real

    def test_every_case_begun_in_the_papers_box_has_a_row_and_the_others_are_named(self):
        # made-up: one finished case, one carried part-way, one not begun, and one of no coupling row
        class Case:
            def __init__(self, name, shape, period, **keys):
                self.row, self.keys = {"case": name}, {"intruder.shape": shape, "drive.period": period, **keys}

            def get(self, key):
                return self.keys.get(key)

        done = (Case("t5", "triangle", 5.0, **{"intruder.surface": "lattice"}),)
        carried = [Case("s3", "square", 3.0, **{"intruder.surface": "lattice"}), Case("s4", "square", 4.0)]
        waiting = Case("t4", "triangle", 4.0, **{"intruder.surface": "lattice"})
        reading = factor_tables.PaperBoxReading
        sig = scatter.clock_sigma("triangle")
        readings = {("triangle", 5.0): reading("triangle", 5.0, 5 * sig, -sig),
                    ("square", 3.0): reading("square", 3.0, 0.06, 0.09, 364.9, 1000.0)}
        fakes = {"committed": lambda folders: ["folder"], "load": lambda folder: done,
                 "unfinished": lambda folder: carried, "cases_of": lambda folder, finished: tuple(carried) + (waiting,),
                 "paper_box_coupling": lambda shape, period, changes: readings[(shape, period)]}
        real = {name: getattr(answer_sentences, name) for name in fakes}
        try:
            for name, fake in fakes.items():
                setattr(answer_sentences, name, fake)
            lines, sources = answer_sentences.answer_paper_box_coupling({})
        finally:
            for name, value in real.items():
                setattr(answer_sentences, name, value)
        self.assertEqual(sources, ["folder"])
        rows = [line for line in lines[2:] if line.startswith("|")]
        self.assertEqual(len(rows), 2)
        self.assertTrue(rows[0].startswith(f"| triangle (OS5) | 5 | the lattice body | V_y {5 * sig:+.3f} (1 bed, +5.0 se), "
                                           "rising, as the paper; against the protocol's"), rows[0])
        self.assertEqual(rows[1], "| square (OS2) | 3 | the lattice body | being run, so far (t = 100-364.9, not judged) "
                                  "+0.0600 against the protocol's +0.0900 on the same bed over the same window (one bed) |")
        self.assertTrue(lines[-1].endswith("; not begun yet: the triangle at T = 4)"), lines[-1])

    def test_a_coupling_change_of_a_straying_shape_says_its_standard_errors_by_that_scatter(self):
        real_straying, real_paired = factor_tables.straying, factor_tables.coupling_paired
        try:
            # paired changes' standard deviation 0.01: one run's 0.01 / sqrt 2; two beds each change +0.01
            factor_tables.straying = lambda shapes: [("square", 0.01, 3, 0.0034)] if "square" in shapes else []
            factor_tables.coupling_paired = lambda shape, period, changes: ([0.03, 0.03], [0.02, 0.02])
            z = round(0.01 / (0.01 / 2 ** 0.5 * (1 / 2 + 1 / 2) ** 0.5), 1)
            change = factor_tables.coupling_change("square", 3.0, {"intruder.rotation": "free"})
            self.assertEqual(change.by_runs, f", {z:.1f} se by the scatter the square's paired runs show")
            # and the words say it where the change is shown
            self.assertIn(f"turning +0.0100 ({abs(change.z):.1f} se, {z:.1f} se by the scatter the square's paired runs show, ",
                          answer_sentences.measured_words([("turning", change)])[0][0])
            # a shape whose paired runs do not stray: nothing to add
            self.assertEqual(factor_tables.coupling_change("triangle", 5.0, {"intruder.rotation": "free"}).by_runs, "")
            # nothing measured yet: no change
            factor_tables.coupling_paired = lambda shape, period, changes: ([], [])
            self.assertIsNone(factor_tables.coupling_change("square", 3.0, {"intruder.rotation": "free"}))
        finally:
            factor_tables.straying, factor_tables.coupling_paired = real_straying, real_paired

    def test_the_change_that_makes_most_of_a_shapes_paired_scatter_is_named(self):
        real = factor_tables.paired_changes
        try:
            # turning's two beds split (sum of squares 2 x 0.075^2); the atoms' mass's agree (2 x 0.001^2); one bed
            # tells nothing
            factor_tables.paired_changes = lambda shape: {("turning", "the triangle at T = 5"): [-0.0035, 0.1465],
                                                          ("the atoms' mass", "the triangle at T = 5"): [0.005, 0.007],
                                                          ("the lattice body", "the triangle at T = 4"): [0.1]}
            name, cell, share = factor_tables.largest_share("triangle")
            self.assertEqual((name, cell), ("turning", "the triangle at T = 5"))
            self.assertAlmostEqual(share, 2 * 0.075 ** 2 / (2 * 0.075 ** 2 + 2 * 0.001 ** 2))
            self.assertEqual(factor_tables.most_of_it("triangle"), ", 100% of it from turning at the triangle at T = 5")
            # no change makes more than half of it: nothing named
            factor_tables.paired_changes = lambda shape: {("a", "x"): [0.0, 0.002], ("b", "y"): [0.0, 0.002]}
            self.assertEqual(factor_tables.most_of_it("triangle"), "")
            # no change of two beds: nothing to share
            factor_tables.paired_changes = lambda shape: {("a", "x"): [0.01]}
            self.assertIsNone(factor_tables.largest_share("triangle"))
        finally:
            factor_tables.paired_changes = real

    def test_a_change_pairs_only_over_its_baselines_very_beds(self):
        class Ran:   # a made-up case: its V_y and the key of the bed it ran on
            def __init__(self, vy, key):
                self.vy, self.key = vy, key

            def get(self, _):
                return self.vy

            def bed_key(self):
                return self.key

        lattice = {"intruder.surface": "lattice"}
        # bed 1 the baseline's own; seed 3 a bed of its own (poured around the body), whatever its seed; seed 4 no
        # baseline at all
        made_up = {(): {1: Ran(0.01, "a"), 2: Ran(0.02, "b"), 3: Ran(0.03, "c")},
                   tuple(lattice.items()): {1: Ran(0.05, "a"), 3: Ran(0.07, "z"), 4: Ran(0.08, "y")}}
        real = factor_tables.coupling_cases
        factor_tables.coupling_cases = lambda shape, period, changes: made_up[tuple(changes.items())]
        try:
            self.assertEqual(factor_tables.shared_beds("triangle", 5.0, lattice), [1])
            self.assertEqual(factor_tables.coupling_paired("triangle", 5.0, lattice), ([0.05], [0.01]))
        finally:
            factor_tables.coupling_cases = real

    def test_a_coupling_change_is_not_resolved_beyond_its_shapes_paired_runs(self):
        real_straying, real_paired = factor_tables.straying, factor_tables.coupling_paired
        sig = scatter.clock_sigma("triangle")
        try:
            # two beds, each side paired: a change of 5 sigma, resolved by sigma (5 se)
            factor_tables.coupling_paired = lambda shape, period, changes: ([5 * sig, 5 * sig], [0.0, 0.0])
            factor_tables.straying = lambda shapes: []
            self.assertEqual(factor_tables.coupling_change("triangle", 5.0, {"intruder.rotation": "free"})[2],
                             "toward the paper")
            # the triangle's paired runs stray: one run's sd 4 sigma, so the change is 1.25 se by them
            factor_tables.straying = lambda shapes: [("triangle", 4 * sig * 2 ** 0.5, 3, sig * 2 ** 0.5)]
            self.assertEqual(factor_tables.coupling_change("triangle", 5.0, {"intruder.rotation": "free"})[2],
                             "within the scatter")
        finally:
            factor_tables.straying, factor_tables.coupling_paired = real_straying, real_paired

    def test_where_a_coupling_factor_by_itself_starts_the_shape_rising(self):
        sig = scatter.clock_sigma("triangle")
        # one period tells no bracket
        self.assertEqual(answer_sentences.coupling_bracket_words("triangle", [(5.0, [8 * sig, 8 * sig])]), "")
        # rising at T = 5 but not at T = 4: the paper's 4-5
        words = answer_sentences.coupling_bracket_words("triangle", [(4.0, [0.0, 0.5 * sig]), (5.0, [8 * sig, 8 * sig])])
        self.assertIn("; by itself there T = 4 ", words)
        self.assertIn(": its bracket 4-5, **yes**", words)
        # rising at both: below the paper's range
        words = answer_sentences.coupling_bracket_words("triangle", [(4.0, [6 * sig, 6 * sig]), (5.0, [8 * sig, 8 * sig])])
        self.assertIn(": its bracket <= 4, **no**", words)
        self.assertEqual(answer_sentences.coupling_bracket_short("triangle", [(4.0, [6 * sig, 6 * sig]), (5.0, [8 * sig] * 2)]),
                         ", its bracket there <= 4 (the paper's 4-5)")
        self.assertEqual(answer_sentences.coupling_bracket_short("triangle", [(5.0, [8 * sig] * 2)]), "")
        lattice_moves = factor_tables.CouplingChange(0.11, 10.2, "toward the paper", "the lattice body", "the triangle at T = 5", 2)
        self.assertIn("(+0.110, 10.2 se, in the 60 d box, its bracket there <= 4 (the paper's 4-5); not run in the paper's",
                      answer_sentences.coupling_status([(lattice_moves, None, ", its bracket there <= 4 (the paper's 4-5)")]))
        # and the words stand after the 60 d box's change in the cell's sentence
        lattice = factor_tables.CouplingChange(0.11, 10.2, "toward the paper", "the lattice body", "the triangle at T = 5", 2)
        self.assertIn("2 beds paired) in the 60 d box; by itself there T = 4 ",
                      answer_sentences.what_is_left([], False, "", [(lattice, None, words)]))

    def test_the_lattice_body_by_itself_shape_by_shape(self):
        sig = scatter.clock_sigma("triangle")
        made_up = {"triangle": [(4.0, [0.5 * sig, 0.0]), (5.0, [8 * sig, 8 * sig])], "disk": [(2.5, [0.0])]}
        real_periods, real_straying = factor_tables.coupling_periods, factor_tables.straying
        factor_tables.coupling_periods = lambda shape, changes: made_up.get(shape, [])
        factor_tables.straying = lambda shapes: []
        try:
            lines, _ = factor_tables.answer_lattice({})
        finally:
            factor_tables.coupling_periods, factor_tables.straying = real_periods, real_straying
        rows = [line for line in lines if line.startswith("| ") and "---" not in line][1:]
        self.assertEqual([r.split(" | ")[0] for r in rows], ["| disk (OS1)", "| triangle (OS5)"])   # shapes run, in order
        self.assertIn("| T = 2.5 +0.000 (1 bed, +0.0 se) | none: not rising at T = 2.5 |", rows[0])
        self.assertIn("| 4-5 | T = 4 ", rows[1])
        self.assertIn("| 4-5 | **yes**", rows[1])   # not rising at 4, rising at 5: the paper's bracket

    def test_the_screen_is_run_once_every_row_has_both_disputed_cells(self):
        real, real_waiting = factor_tables.coupling_change, factor_tables.disputed_cases_waiting
        try:
            factor_tables.disputed_cases_waiting = lambda: []
            # every row measured at both disputed cells, whatever else is not: run
            factor_tables.coupling_change = lambda shape, period, changes: (
                (0.0, 0.0, "within the scatter") if (shape, period) in factor_tables.DISPUTED_CELLS else None)
            self.assertTrue(factor_tables.coupling_screen_run())
            # the velocity reading not at the triangle's cell yet: still being run
            factor_tables.coupling_change = lambda shape, period, changes: (
                None if changes == {"drive.form": "velocity"} and shape == "triangle" else (0.0, 0.0, "within the scatter"))
            self.assertFalse(factor_tables.coupling_screen_run())
            # every row measured, but a case at a disputed cell still to finish: still being run
            factor_tables.coupling_change = lambda shape, period, changes: (0.0, 0.0, "within the scatter")
            self.assertTrue(factor_tables.coupling_screen_run())
            factor_tables.disputed_cases_waiting = lambda: ["triangle_T5_free_s4"]
            self.assertFalse(factor_tables.coupling_screen_run())
        finally:
            factor_tables.coupling_change, factor_tables.disputed_cases_waiting = real, real_waiting

    def test_the_coupling_screen_at_one_cell(self):
        atom = factor_tables.CouplingChange(-0.0042, -1.8, "within the scatter", "the atoms' mass", "the square at T = 3", 2)
        self.assertEqual(answer_sentences.cell_coupling_status([("the atoms' mass", atom), ("turning", None)]),
                         "its screen being run, at this cell the atoms' mass -0.0042 (1.8 se, within the scatter; "
                         "2 beds paired); not run here yet: turning; study/VALIDATION.md, \"The intruder's coupling\"")
        self.assertEqual(answer_sentences.cell_coupling_status([("turning", None)]),
                         "its screen being run, not at this cell yet; study/VALIDATION.md, \"The intruder's coupling\"")
        # once every row has run at both disputed cells, the screen is said to be run
        self.assertTrue(answer_sentences.cell_coupling_status([("the atoms' mass", atom)], True).startswith(
            "its screen run, at this cell the atoms' mass -0.0042"))

    def test_the_paired_changes_own_scatter_is_pooled_by_shape(self):
        # made-up screen: (V_y with the change, the baseline's) per bed, by cell and factor
        screen = {("square", 3.0, "intruder.contact_mass"): ([0.019, 0.018], [0.023, 0.022]),   # changes -0.004, -0.004
                  ("square", 4.0, "intruder.contact_mass"): ([0.066], [0.050]),                 # one bed: tells nothing
                  ("triangle", 5.0, "intruder.contact_mass"): ([-0.024, -0.025], [-0.030, -0.030]),   # +0.006, +0.005
                  ("triangle", 5.0, "intruder.surface"): ([0.078, 0.081], [-0.030, -0.030])}          # +0.108, +0.111

        def made_up(shape, period, changes):
            return screen.get((shape, period, next(iter(changes))), ([], []))
        real, factor_tables.coupling_paired = factor_tables.coupling_paired, made_up
        try:
            self.assertEqual(factor_tables.paired_scatter("square")[1], 1)
            self.assertAlmostEqual(factor_tables.paired_scatter("square")[0], 0.0, places=12)
            sigma, dof = factor_tables.paired_scatter("triangle")
            # squares (0.0005^2 x 2) + (0.0015^2 x 2) over 1 + 1 degrees of freedom
            self.assertEqual(dof, 2)
            self.assertAlmostEqual(sigma, ((0.0005 ** 2 * 2 + 0.0015 ** 2 * 2) / 2) ** 0.5)
            # the lattice pair's squares are 0.0015^2 x 2 of the whole: 90 %
            self.assertIn("square 0.0000 (1 dof), triangle 0.0016 (2 dof, 90% of it from the lattice body at the "
                          "triangle at T = 5), disk not measured yet; the rule takes",
                          factor_tables.paired_scatter_words(["square", "triangle", "disk"]))
        finally:
            factor_tables.coupling_paired = real

    def test_a_shape_whose_paired_changes_stray_more_than_its_sigma_is_named(self):
        # the square's two paired changes -0.006 and +0.012 (sd 0.0127, 1 dof) against a sigma of 0.0024
        # (sigma sqrt 2 = 0.0034); the triangle's +0.109 and +0.111 (sd 0.0014) against 0.0108
        screen = {("square", 3.0): ([0.017, 0.034], [0.023, 0.022]), ("triangle", 5.0): ([0.078, 0.080], [-0.031, -0.031])}
        sigmas = {"square": 0.0024, "triangle": 0.0108}
        real = factor_tables.coupling_paired, factor_tables.clock_sigma
        factor_tables.coupling_paired = lambda shape, period, changes: (
            screen.get((shape, period), ([], [])) if "intruder.surface" in changes else ([], []))
        factor_tables.clock_sigma = sigmas.get
        try:
            [(shape, sd, dof, rule)] = factor_tables.straying(["square", "triangle"])
            self.assertEqual((shape, dof), ("square", 1))
            self.assertAlmostEqual(sd, 0.018 / 2 ** 0.5)
            self.assertAlmostEqual(rule, 0.0024 * 2 ** 0.5)
            self.assertIn("; the square's is 3.8 x the rule's sigma sqrt 2 (0.0034): its changes' counts of standard "
                          "errors overstate them by as much", factor_tables.paired_scatter_words(["square", "triangle"]))
            self.assertIn("the square's paired runs on one bed stray 3.8 x as far as its sigma allows (1 dof, 100% of "
                          "it from the lattice body at the square at T = 3)", answer_sentences.straying_note())
            sigmas["square"] = 0.01   # a sigma that allows the spread: nothing named
            self.assertEqual(factor_tables.straying(["square", "triangle"]), [])
            self.assertEqual(answer_sentences.straying_note(), "")
        finally:
            factor_tables.coupling_paired, factor_tables.clock_sigma = real


if __name__ == "__main__":
    unittest.main()
