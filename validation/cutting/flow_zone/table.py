"""The flow-zone runs' figures (validation/cutting/README.md) from their summary.json files.

    python3 validation/cutting/flow_zone/table.py OUT_DIR > validation/cutting/flow_zone/results.csv
"""
import csv
import json
import os
import sys

RUNS = [  # name, friction law, mu, flow zone, cutting speed (m/min), the tool's share of the friction heat
    ("fz200", "spring", 0.5, True, 200, 0.5), ("fz600", "spring", 0.5, True, 600, 0.5),
    ("s200", "spring", 2.0, True, 200, 0.5), ("s600", "spring", 2.0, True, 600, 0.5),
    ("n600", "spring", 2.0, False, 600, 0.5),
    ("r200", "regularized", 2.0, True, 200, 0.5), ("r600", "regularized", 2.0, True, 600, 0.5),
    ("rn200", "regularized", 2.0, False, 200, 0.5), ("rn600", "regularized", 2.0, False, 600, 0.5),
    ("z200", "spring", 0.5, True, 200, 0.0), ("z600", "spring", 0.5, True, 600, 0.0),
]


def main(out):
    w = csv.writer(sys.stdout)
    w.writerow(["run", "friction_law", "mu_1", "flow_zone", "speed_m_per_min", "tool_friction_share_1",
                "Fc_per_width_N_per_m",
                "Fc_ci95_N_per_m", "Ft_per_width_N_per_m", "Ft_ci95_N_per_m", "friction_angle_deg",
                "chip_thickness_m", "rake_face_hottest_particle_K"])
    for name, law, mu, fz, v, share in RUNS:
        path = os.path.join(out, name, "summary.json")
        if not os.path.exists(path):
            print(f"{path}: missing (run.sh not finished?)", file=sys.stderr)
            continue
        s = json.load(open(path))
        c, ch = s["cutting"], s.get("chip", {})
        w.writerow([name, law, mu, fz, v, share, c["cutting_force_per_width_mean_N_per_m"],
                    c["cutting_force_per_width_ci95_N_per_m"], c["thrust_force_per_width_mean_N_per_m"],
                    c["thrust_force_per_width_ci95_N_per_m"], ch.get("friction_angle_deg"),
                    ch.get("thickness_m"), ch.get("rake_face_temperature_K")])


if __name__ == "__main__":
    main(sys.argv[1])
