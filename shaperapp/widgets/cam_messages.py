"""The feed cam's refusals in the UI's language: core.cam's English patterns and their
translatable templates, so the Chinese Cam tab shows no English sentence.

A part of :mod:`shaperapp.widgets.messages`' one table (which reads these first with its
own): the cam's messages are many and their own concern. A refusal whose advice follows
"; " is matched clause by clause: its statement here, its advice in ADVICE_PATTERNS.
"""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication

# (pattern on core.cam's English ``allowed`` text, translatable template with %1, %2 …)
PATTERNS: tuple[tuple[str, str], ...] = (
    (r"rise \+ outer dwell \+ return must fit in 360° \(they add up to (\S+)°\)$",
     "rise + outer dwell + return must fit in 360° (they add up to %1°)"),
    (r"rise \+ outer dwell \+ return \((\S+)°\) must fit in the (\S+)° the crank turns outside the cut$",
     "rise + outer dwell + return (%1°) must fit in the %2° the crank turns outside the cut"),
    (r"feeds during the cut: the rise must start between (\S+)° and (\S+)° of crank angle$",
     "feeds during the cut: the rise must start between %1° and %2° of crank angle"),
    (r"too large: must be ≤ (\S+) mm .*ρmin is (\S+) mm, .*$",
     "too large: must be at most %1 mm, or it undercuts the profile (smallest convex radius of the pitch curve %2 mm)"),
    (r"is too small: no cam within (\S+) arm lengths keeps the pressure angle within the allowances$",
     "is too small: no cam within %1 arm lengths keeps the pressure angle within the allowances"),
    (r"must be between \|a − l\| = (\S+) mm and a \+ l = (\S+) mm for the arm to reach the cam$",
     "must be between |a − l| = %1 mm and a + l = %2 mm for the arm to reach the cam"),
    (r"gives an arm that crosses the line of centres at the end of its swing; give a base radius below (\S+) "
     r"mm$",
     "gives an arm that crosses the line of centres at the end of its swing; give a base radius below %1 mm"),
    (r"gives an arm that crosses the line of centres; choose another base radius$",
     "gives an arm that crosses the line of centres; choose another base radius"),
    (r"give --base and --distance together to check a cam$",
     "give the base radius and the centre distance together to check a cam"),
    # a cam that does not fit its hub or the follower pivot's boss (core.cam.build)
    (r"the profile's smallest radius r0 − r = (\S+) mm is (\S+) mm short of hub \+ clearance = (\S+) mm$",
     "the profile's smallest radius r0 − r = %1 mm is %2 mm short of hub + clearance = %3 mm"),
    (r"the profile's largest radius (\S+) mm reaches (\S+) mm past a − boss − clearance = (\S+) mm$",
     "the profile's largest radius %1 mm reaches %2 mm past a − boss − clearance = %3 mm"),
    (r"no cam within the allowances clears the pivot boss; the smallest: the profile's largest radius (\S+) mm "
     r"reaches (\S+) mm past a − boss − clearance = (\S+) mm$",
     "no cam within the allowances clears the pivot boss; the smallest: its profile's largest radius %1 mm "
     "reaches %2 mm past a − boss − clearance = %3 mm"),
    # an automatic roller of at least 3 mm (core.cam.cam)
    (r"no cam within the allowances takes a roller of (\S+) mm or more and clears the hub and the pivot boss; "
     r"an arm of (\S+) mm gives one$",
     "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss; "
     "an arm of %2 mm gives one"),
    (r"no cam within the allowances takes a roller of (\S+) mm or more and clears the hub and the pivot boss, "
     r"with any arm up to (\S+) mm$",
     "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss, "
     "with any arm up to %2 mm"),
    # a typed roller (core.cam.roller_range, core.cam.cam)
    (r"too large for the hub: must be ≤ (\S+) mm, so that the profile's smallest radius r0 − r stays ≥ hub "
     r"\+ clearance = (\S+) mm$",
     "too large for the hub: must be at most %1 mm, so that the profile's smallest radius r0 − r stays at "
     "least hub + clearance = %2 mm"),
    (r"must be between (\S+) and (\S+) mm on this cam: at least (\S+) mm for the profile's largest radius "
     r"R1 − r to stay within a − boss − clearance = (\S+) mm, at most (\S+) mm for it to clear the hub and "
     r"stay round \(ρmin = (\S+) mm\)$",
     "must be between %1 and %2 mm on this cam: at least %3 mm for the profile's largest radius R1 − r to "
     "stay within a − boss − clearance = %4 mm, at most %5 mm for it to clear the hub and stay round "
     "(ρmin = %6 mm)"),
    (r"no cam within the allowances takes a roller of (\S+) mm and clears the hub and the pivot boss; "
     r"an arm of (\S+) mm gives one$",
     "no cam within the allowances takes a roller of %1 mm and clears the hub and the pivot boss; "
     "an arm of %2 mm gives one"),
    (r"no cam within the allowances takes a roller of (\S+) mm and clears the hub and the pivot boss, "
     r"with any arm up to (\S+) mm$",
     "no cam within the allowances takes a roller of %1 mm and clears the hub and the pivot boss, "
     "with any arm up to %2 mm"),
    # the first clause of a refusal whose advice follows "; " (ADVICE_PATTERNS)
    (r"the pitch curve's smallest convex radius ρmin = (\S+) mm takes no roller of (\S+) mm or more "
     r"\(that needs ρmin ≥ (\S+) mm\)$",
     "the pitch curve's smallest convex radius ρmin = %1 mm takes no roller of %2 mm or more (that needs "
     "ρmin ≥ %3 mm)"),
    (r"this cam takes no roller: its pitch curve's smallest convex radius ρmin = (\S+) mm and "
     r"r0 − hub − clearance = (\S+) mm leave no room for one$",
     "this cam takes no roller: its pitch curve's smallest convex radius ρmin = %1 mm and "
     "r0 − hub − clearance = %2 mm leave no room for one"),
    (r"this cam takes no roller: the hub and ρmin = (\S+) mm allow one of at most (\S+) mm, the pivot boss "
     r"needs one of at least (\S+) mm$",
     "this cam takes no roller: the hub and ρmin = %1 mm allow one of at most %2 mm, the pivot boss needs "
     "one of at least %3 mm"),
    (r"the smallest cam for the allowances takes no roller of (\S+) mm or more \(ρmin = (\S+) mm\)$",
     "the smallest cam for the allowances takes no roller of %1 mm or more (ρmin = %2 mm)"),
    (r"no roller up to the smallest cam's largest gives a cam within the allowances that clears the hub and "
     r"the pivot boss$",
     "no roller up to the smallest cam's largest gives a cam within the allowances that clears the hub and "
     "the pivot boss"),
    # said while the advice is looked for (core.cam.pending: SEEKING in ADVICE_PATTERNS)
    (r"no whole cam takes a roller of (\S+) mm with these inputs$",
     "no whole cam takes a roller of %1 mm with these inputs"),
    (r"no cam within the allowances takes a roller of (\S+) mm or more and clears the hub and the pivot boss$",
     "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss"),
)

ADVICE_PATTERNS: tuple[tuple[str, str], ...] = (
    (r"leave out the base radius and the centre distance, and the synthesis gives r0 = (\S+) mm for this "
     r"roller$",
     "leave the base radius and the centre distance blank, and the synthesis gives r0 = %1 mm for this roller"),
    (r"leave out the base radius and the centre distance, and the synthesis gives r0 = (\S+) mm with a "
     r"roller of (\S+) mm$",
     "leave the base radius and the centre distance blank, and the synthesis gives r0 = %1 mm with a roller "
     "of %2 mm"),
    (r"leave out the base radius, the centre distance and the roller, and the synthesis gives r0 = (\S+) mm "
     r"with a roller of (\S+) mm$",
     "leave the base radius, the centre distance and the roller blank, and the synthesis gives r0 = %1 mm "
     "with a roller of %2 mm"),
    (r"leave out the base radius and the centre distance, and an arm of (\S+) mm gives one$",
     "leave the base radius and the centre distance blank, and an arm of %1 mm gives one"),
    (r"leave out the base radius, the centre distance and the roller, and an arm of (\S+) mm gives one$",
     "leave the base radius, the centre distance and the roller blank, and an arm of %1 mm gives one"),
    (r"no synthesized cam takes one either, with any arm up to (\S+) mm$",
     "no synthesized cam takes one either, with any arm up to %1 mm"),
    (r"left blank, the roller is (\S+) mm on a base radius raised to (\S+) mm$",
     "left blank, the roller is %1 mm on a base radius raised to %2 mm"),
    (r"an allowance of (\S+)° gives one$", "an allowance of %1° gives one"),
    (r"a base radius of (\S+) mm gives one$", "a base radius of %1 mm gives one"),
    (r"a centre distance of (\S+) mm gives one$", "a centre distance of %1 mm gives one"),
    (r"a return allowance of (\S+)° gives one$", "a return allowance of %1° gives one"),
    (r"(\S+)° on the rise and the return give one$", "%1° on the rise and the return give one"),
    (r"a swing of (\S+)° gives one$", "a swing of %1° gives one"),
    (r"an arm of (\S+) mm gives one \(no swing down to (\S+)° does\)$",
     "an arm of %1 mm gives one (no swing down to %2° does)"),
    (r"a swing of (\S+)° gives one \(no allowance up to (\S+)° does\)$",
     "a swing of %1° gives one (no allowance up to %2° does)"),
    (r"no allowance up to (\S+)° gives one, nor a smaller swing: change the arm, the program, the hub, the pivot "
     r"boss or the clearance$",
     "no allowance up to %1° gives one, nor a smaller swing: change the arm, the program, the hub, the pivot boss "
     "or the clearance"),
    (r"leave the roller blank, and a swing of (\S+)° gives one$",
     "leave the roller blank, and a swing of %1° gives one"),
    (r"leave the roller blank, and an arm of (\S+) mm gives one$",
     "leave the roller blank, and an arm of %1 mm gives one"),
    (r"no smaller swing gives one either, nor, with the roller left blank, a swing or an arm: change the hub, the "
     r"pivot boss, the clearance, the allowances or the program$",
     "no smaller swing gives one either, nor, with the roller left blank, a swing or an arm: change the hub, the "
     "pivot boss, the clearance, the allowances or the program"),
    (r"looking for a swing, else an arm, that gives one…$", "looking for a swing, else an arm, that gives one…"),
    (r"looking for a roller, else another value, that gives one…$",
     "looking for a roller, else another value, that gives one…"),
    (r"looking for the least allowance, else a swing, that gives one…$",
     "looking for the least allowance, else a swing, that gives one…"),
    (r"looking for an arm that gives one…$", "looking for an arm that gives one…"),
    (r"looking for what leaving the cam to the synthesis gives…$",
     "looking for what leaving the cam to the synthesis gives…"),
)


def templates() -> dict[str, str]:
    # Listed literally so pyside6-lupdate finds every template.
    return {
        "rise + outer dwell + return must fit in 360° (they add up to %1°)":
            QCoreApplication.translate("messages", "rise + outer dwell + return must fit in 360° (they add up to %1°)"),
        "rise + outer dwell + return (%1°) must fit in the %2° the crank turns outside the cut":
            QCoreApplication.translate("messages", "rise + outer dwell + return (%1°) must fit in the %2° the crank turns outside the cut"),
        "feeds during the cut: the rise must start between %1° and %2° of crank angle":
            QCoreApplication.translate("messages", "feeds during the cut: the rise must start between %1° and %2° of crank angle"),
        "too large: must be at most %1 mm, or it undercuts the profile (smallest convex radius of the pitch curve %2 mm)":
            QCoreApplication.translate("messages", "too large: must be at most %1 mm, or it undercuts the profile (smallest convex radius of the pitch curve %2 mm)"),
        "is too small: no cam within %1 arm lengths keeps the pressure angle within the allowances":
            QCoreApplication.translate("messages", "is too small: no cam within %1 arm lengths keeps the pressure angle within the allowances"),
        "must be between |a − l| = %1 mm and a + l = %2 mm for the arm to reach the cam":
            QCoreApplication.translate("messages", "must be between |a − l| = %1 mm and a + l = %2 mm for the arm to reach the cam"),
        "gives an arm that crosses the line of centres at the end of its swing; give a base radius below %1 mm":
            QCoreApplication.translate("messages", "gives an arm that crosses the line of centres at the end of its swing; give a base radius below %1 mm"),
        "gives an arm that crosses the line of centres; choose another base radius":
            QCoreApplication.translate("messages", "gives an arm that crosses the line of centres; choose another base radius"),
        "give the base radius and the centre distance together to check a cam":
            QCoreApplication.translate("messages", "give the base radius and the centre distance together to check a cam"),
        "the profile's smallest radius r0 − r = %1 mm is %2 mm short of hub + clearance = %3 mm":
            QCoreApplication.translate("messages", "the profile's smallest radius r0 − r = %1 mm is %2 mm short of hub + clearance = %3 mm"),
        "the profile's largest radius %1 mm reaches %2 mm past a − boss − clearance = %3 mm":
            QCoreApplication.translate("messages", "the profile's largest radius %1 mm reaches %2 mm past a − boss − clearance = %3 mm"),
        "no cam within the allowances clears the pivot boss; the smallest: its profile's largest radius %1 mm reaches %2 mm past a − boss − clearance = %3 mm":
            QCoreApplication.translate("messages", "no cam within the allowances clears the pivot boss; the smallest: its profile's largest radius %1 mm reaches %2 mm past a − boss − clearance = %3 mm"),
        "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss; an arm of %2 mm gives one":
            QCoreApplication.translate("messages", "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss; an arm of %2 mm gives one"),
        "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss, with any arm up to %2 mm":
            QCoreApplication.translate("messages", "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss, with any arm up to %2 mm"),
        "too large for the hub: must be at most %1 mm, so that the profile's smallest radius r0 − r stays at least hub + clearance = %2 mm":
            QCoreApplication.translate("messages", "too large for the hub: must be at most %1 mm, so that the profile's smallest radius r0 − r stays at least hub + clearance = %2 mm"),
        "must be between %1 and %2 mm on this cam: at least %3 mm for the profile's largest radius R1 − r to stay within a − boss − clearance = %4 mm, at most %5 mm for it to clear the hub and stay round (ρmin = %6 mm)":
            QCoreApplication.translate("messages", "must be between %1 and %2 mm on this cam: at least %3 mm for the profile's largest radius R1 − r to stay within a − boss − clearance = %4 mm, at most %5 mm for it to clear the hub and stay round (ρmin = %6 mm)"),
        "no cam within the allowances takes a roller of %1 mm and clears the hub and the pivot boss; an arm of %2 mm gives one":
            QCoreApplication.translate("messages", "no cam within the allowances takes a roller of %1 mm and clears the hub and the pivot boss; an arm of %2 mm gives one"),
        "no cam within the allowances takes a roller of %1 mm and clears the hub and the pivot boss, with any arm up to %2 mm":
            QCoreApplication.translate("messages", "no cam within the allowances takes a roller of %1 mm and clears the hub and the pivot boss, with any arm up to %2 mm"),
        "the pitch curve's smallest convex radius ρmin = %1 mm takes no roller of %2 mm or more (that needs ρmin ≥ %3 mm)":
            QCoreApplication.translate("messages", "the pitch curve's smallest convex radius ρmin = %1 mm takes no roller of %2 mm or more (that needs ρmin ≥ %3 mm)"),
        "this cam takes no roller: its pitch curve's smallest convex radius ρmin = %1 mm and r0 − hub − clearance = %2 mm leave no room for one":
            QCoreApplication.translate("messages", "this cam takes no roller: its pitch curve's smallest convex radius ρmin = %1 mm and r0 − hub − clearance = %2 mm leave no room for one"),
        "this cam takes no roller: the hub and ρmin = %1 mm allow one of at most %2 mm, the pivot boss needs one of at least %3 mm":
            QCoreApplication.translate("messages", "this cam takes no roller: the hub and ρmin = %1 mm allow one of at most %2 mm, the pivot boss needs one of at least %3 mm"),
        "the smallest cam for the allowances takes no roller of %1 mm or more (ρmin = %2 mm)":
            QCoreApplication.translate("messages", "the smallest cam for the allowances takes no roller of %1 mm or more (ρmin = %2 mm)"),
        "no roller up to the smallest cam's largest gives a cam within the allowances that clears the hub and the pivot boss":
            QCoreApplication.translate("messages", "no roller up to the smallest cam's largest gives a cam within the allowances that clears the hub and the pivot boss"),
        "leave the base radius and the centre distance blank, and the synthesis gives r0 = %1 mm for this roller":
            QCoreApplication.translate("messages", "leave the base radius and the centre distance blank, and the synthesis gives r0 = %1 mm for this roller"),
        "leave the base radius and the centre distance blank, and the synthesis gives r0 = %1 mm with a roller of %2 mm":
            QCoreApplication.translate("messages", "leave the base radius and the centre distance blank, and the synthesis gives r0 = %1 mm with a roller of %2 mm"),
        "leave the base radius, the centre distance and the roller blank, and the synthesis gives r0 = %1 mm with a roller of %2 mm":
            QCoreApplication.translate("messages", "leave the base radius, the centre distance and the roller blank, and the synthesis gives r0 = %1 mm with a roller of %2 mm"),
        "leave the base radius and the centre distance blank, and an arm of %1 mm gives one":
            QCoreApplication.translate("messages", "leave the base radius and the centre distance blank, and an arm of %1 mm gives one"),
        "leave the base radius, the centre distance and the roller blank, and an arm of %1 mm gives one":
            QCoreApplication.translate("messages", "leave the base radius, the centre distance and the roller blank, and an arm of %1 mm gives one"),
        "no synthesized cam takes one either, with any arm up to %1 mm":
            QCoreApplication.translate("messages", "no synthesized cam takes one either, with any arm up to %1 mm"),
        "left blank, the roller is %1 mm on a base radius raised to %2 mm":
            QCoreApplication.translate("messages", "left blank, the roller is %1 mm on a base radius raised to %2 mm"),
        "an allowance of %1° gives one": QCoreApplication.translate("messages", "an allowance of %1° gives one"),
        "a base radius of %1 mm gives one": QCoreApplication.translate("messages", "a base radius of %1 mm gives one"),
        "a centre distance of %1 mm gives one":
            QCoreApplication.translate("messages", "a centre distance of %1 mm gives one"),
        "a return allowance of %1° gives one":
            QCoreApplication.translate("messages", "a return allowance of %1° gives one"),
        "%1° on the rise and the return give one":
            QCoreApplication.translate("messages", "%1° on the rise and the return give one"),
        "a swing of %1° gives one": QCoreApplication.translate("messages", "a swing of %1° gives one"),
        "an arm of %1 mm gives one (no swing down to %2° does)":
            QCoreApplication.translate("messages", "an arm of %1 mm gives one (no swing down to %2° does)"),
        "no whole cam takes a roller of %1 mm with these inputs":
            QCoreApplication.translate("messages", "no whole cam takes a roller of %1 mm with these inputs"),
        "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss":
            QCoreApplication.translate("messages", "no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss"),
        "a swing of %1° gives one (no allowance up to %2° does)":
            QCoreApplication.translate("messages", "a swing of %1° gives one (no allowance up to %2° does)"),
        "no allowance up to %1° gives one, nor a smaller swing: change the arm, the program, the hub, the pivot boss or the clearance":
            QCoreApplication.translate("messages", "no allowance up to %1° gives one, nor a smaller swing: change the arm, the program, the hub, the pivot boss or the clearance"),
        "leave the roller blank, and a swing of %1° gives one":
            QCoreApplication.translate("messages", "leave the roller blank, and a swing of %1° gives one"),
        "leave the roller blank, and an arm of %1 mm gives one":
            QCoreApplication.translate("messages", "leave the roller blank, and an arm of %1 mm gives one"),
        "no smaller swing gives one either, nor, with the roller left blank, a swing or an arm: change the hub, the pivot boss, the clearance, the allowances or the program":
            QCoreApplication.translate("messages", "no smaller swing gives one either, nor, with the roller left blank, a swing or an arm: change the hub, the pivot boss, the clearance, the allowances or the program"),
        "looking for a swing, else an arm, that gives one…":
            QCoreApplication.translate("messages", "looking for a swing, else an arm, that gives one…"),
        "looking for a roller, else another value, that gives one…":
            QCoreApplication.translate("messages", "looking for a roller, else another value, that gives one…"),
        "looking for the least allowance, else a swing, that gives one…":
            QCoreApplication.translate("messages", "looking for the least allowance, else a swing, that gives one…"),
        "looking for an arm that gives one…": QCoreApplication.translate("messages", "looking for an arm that gives one…"),
        "looking for what leaving the cam to the synthesis gives…":
            QCoreApplication.translate("messages", "looking for what leaving the cam to the synthesis gives…"),
    }
