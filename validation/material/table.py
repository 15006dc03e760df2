#!/usr/bin/python3
"""The material lab's README tables from material.json files (swarf material).
Usage: table.py DEFAULT_JSON C45_JSON [C45_NOFAIL_JSON]. Prints markdown."""
import json, sys

TESTS = ["tension100", "tension110", "compression100", "shear100", "shear45", "cyclic100"]


def mpa(v):
    return "-" if v is None else "%.0f" % (v / 1e6)


def num(v, f="%.3g"):
    return "-" if v is None else f % v


def table(path):
    j = json.load(open(path))
    L = j["lattice"]
    print("Case `%s`: E100 = %.1f GPa, E110 = %.1f GPa, C44 = %.1f GPa, (C11-C12)/2 = %.1f GPa\n"
          % (j["case"], L["E100_Pa"] / 1e9, L["E110_Pa"] / 1e9, L["C44_Pa"] / 1e9,
             (L["C11_Pa"] - L["C12_Pa"]) / 2e9))
    print("| test | initial modulus [GPa] | yield (0.2 %) [MPa] | flow at eps_p 0.1 | 0.5 | 1 [MPa] | "
          "failure strain | peak [MPa] at strain | end det F | end plastic volume strain | contact at strain |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for t in TESTS:
        if t not in j["tests"]:
            continue
        s = j["tests"][t]
        f = s["flow_stress_Pa"]
        print("| %s | %.1f | %s | %s | %s | %s | %s | %s at %s | %s | %s | %s |" % (
            t, s["initial_modulus_Pa"] / 1e9, mpa(s["yield_stress_Pa"]), mpa(f["0.1"]), mpa(f["0.5"]), mpa(f["1"]),
            num(s["failure_strain"], "%.4g"), mpa(s["peak_equivalent_stress_Pa"]), num(s["peak_strain"], "%.3g"),
            num(s["end_volume_ratio"], "%.3f"), num(s["end_plastic_volume_strain"], "%.3f"),
            num(s["contact_strain"], "%.4g") + (" (collapsed)" if s["collapsed"] else "")))
    a = j["anisotropy"] or {}
    print("\nAnisotropy: E110/E100 = %s, Zener ratio = %s, yield 110/100 = %s, flow 110/100 at 0.1 = %s, "
          "yield shear45/shear100 = %s" % (
              num(a.get("E110_over_E100"), "%.4f"), num(a.get("zener_ratio"), "%.4f"),
              num(a.get("yield_110_over_100"), "%.3f"), num(a.get("flow_110_over_100", {}).get("0.1"), "%.3f"),
              num(a.get("yield_shear45_over_shear100"), "%.3f")))
    for sh in ("shear100", "shear45"):
        ts = a.get("tau_over_sigma", {}).get(sh, {})
        print("tau/sigma (%s over tension100): %s" % (sh, ", ".join(
            "%s at eps_p %s" % (num(ts.get(k), "%.3f"), k) for k in ("0.002", "0.1", "0.5", "1"))))
    ct = a.get("compression_over_tension_100", {})
    print("|compression|/tension along [100]: %s" % ", ".join(
        "%s at eps_p %s" % (num(ct.get(k), "%.3f"), k) for k in ("0.002", "0.1", "0.5", "1")))
    for t in ("tension100", "compression100", "tension110", "shear100", "shear45"):
        if t in j["tests"]:
            r = j["tests"][t].get("over_small_strain_mapping", {})
            print("%s over its small-strain mapping: %s" % (t, ", ".join(
                "%s at %s" % (num(r.get(k), "%.3f"), k) for k in ("0.01", "0.1", "0.5", "1"))))
    print()


for p in sys.argv[1:]:
    table(p)
