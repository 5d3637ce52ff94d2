#!/usr/bin/env python3
"""Writes the paper's slope scenarios (scenarios/paper-slope-*.json).

Geometry and soil follow the reconstruction described in docs/method.md,
section 3.10: a 10 m high slope at 40 degrees, crest from x = 0 to 43.95 m, toe at
55.87 m, a 6 m x 4 m elastic house 2 m behind the crest edge, 60 m of runout
floor right of the toe. Rerun after changing anything here; the JSON files are
what the program reads.
"""
import json
import math
import pathlib

H = 10.0
CREST = 43.95
TOE = CREST + H / math.tan(math.radians(40.0))  # 55.87 m
RIGHT = 116.0   # >= 60 m right of the toe
TOP = 20.0

# Cell size per point count (method notes section 3).
RESOLUTIONS = {1648: 1.127, 8370: 0.5, 28724: 0.270, 67016: 0.177}
# The points each cell size seeds (`landslide check` prints them): the files
# are named by these, so a name says what the scene holds.
SEEDED = {1648: 1661, 8370: 8370, 28724: 28711, 67016: 66787}

# Friction angle of the soil before the trigger, the same in every scene. With
# 40 kPa of cohesion the slope never yields in the gravity stage at any of the
# four angles (f < 0 everywhere: tests/sim/test_paper_slope.cpp), and an
# elastic state does not depend on the friction angle. So the trigger removes
# the cohesion and sets the scene's angle, and the scenes of one resolution
# share one gravity stage, which `landslide gallery` computes once.
PHI_BEFORE_TRIGGER = 25

# Below this density the soil is disconnected and carries no stress
# (Dunatunga & Kamrin 2015, sim/physics/granular.hpp): a reconstruction, the density
# as placed (scenarios/README.md says why).
CRITICAL_DENSITY = 2000


# The region of interest of the slides that stay within it: from the back of
# the failure (the 20 degree line from the toe reaches the crest's height at
# x = 28 m) to past the deposit's front (toe + runout: 69 m at phi = 25, 75 to
# 76 m at phi = 20 with 1661 and 8370 points), 1 m below the floor to 1 m
# above the house. 50 m wide, so a 1280 px frame shows the 10 m slope at
# least 200 px tall (tests/app/test_frame_view.cpp). The finer phi = 20 scenes
# run out to 78 and 82 m, and phi = 15 and 10 to the far wall: they are
# painted in the view the material occupies (scenarios/README.md, output.view).
VIEW = {"min": [28, -1], "max": [78, 15]}
WITH_VIEW = {(25, 8370), (20, 8370), (20, 1648)}


def output(phi, points):
    out = {"frame_interval": 0.5, "frame_stages": ["slide"],
           "fields": ["displacement-x", "relative-yield"], "colour_map": "jet",
           "displacement_reference": "initial", "vtk": "stage-end",
           "image_size": [1280, "auto"]}
    if (phi, points) in WITH_VIEW:
        out["view"] = VIEW
    return out


def scenario(phi, points, name):
    h = RESOLUTIONS[points]
    count = (f"about {points} points (h = {h} m)" if SEEDED[points] == points
             else f"{SEEDED[points]} points (h = {h} m; the paper's {points})")
    return {
        "name": name,
        "description": (
            f"The paper's 40 degree slope with a house (Andersen & Andersen), friction {phi} deg "
            f"after the trigger, {count}. Gravity is ramped in with "
            f"cohesion 40 kPa (the soil stays elastic, so its friction angle, "
            f"{PHI_BEFORE_TRIGGER} deg until the trigger, does not matter); the trigger "
            "removes the cohesion and sets the friction angle; the slide runs until at rest."),
        "domain": {"min": [0, 0], "max": [RIGHT, TOP]},
        "grid": {"cell_size": h, "padding_cells": 2, "points_per_cell": 2},
        "gravity": [0, -9.81],
        "boundaries": {"left": "roller", "right": "roller", "bottom": "fixed", "top": "free"},
        "materials": {
            "soil": {"model": "mohr-coulomb", "density": 2000, "youngs_modulus": 20e6,
                     "poisson_ratio": 0.25, "cohesion": 40e3, "friction_angle": PHI_BEFORE_TRIGGER,
                     "dilation_angle": min(10, phi), "critical_density": CRITICAL_DENSITY},
            "house": {"model": "linear-elastic", "density": 500, "youngs_modulus": 20e6,
                      "poisson_ratio": 0.25},
        },
        "bodies": [
            {"name": "slope", "material": "soil",
             "polygon": [[0, 0], [round(TOE, 2), 0], [CREST, H], [0, H]]},
            {"name": "house", "material": "house",
             "rectangle": {"min": [CREST - 8.0, H], "max": [CREST - 2.0, H + 4.0]}},
        ],
        "time_step": {"courant": 0.5},
        "stages": [
            {"name": "gravity", "type": "gravity", "duration": 5.0, "ramp_fraction": 0.5,
             "damping": 0.01},
            {"name": "trigger", "type": "material-change", "material": "soil",
             "set": {"cohesion": 0, "friction_angle": phi}},
            {"name": "slide", "type": "dynamic", "duration": 40.0,
             "stop_at_rest": {"kinetic_ratio": 1e-4, "min_time": 2.0}},
        ],
        "output": output(phi, points),
    }


def main():
    out = pathlib.Path(__file__).resolve().parent.parent / "scenarios"
    files = {f"paper-slope-phi{phi}": (phi, 8370) for phi in (25, 20, 15, 10)}
    files.update({f"paper-slope-phi20-n{SEEDED[n]}": (20, n) for n in (1648, 28724, 67016)})
    for name, (phi, points) in files.items():
        text = json.dumps(scenario(phi, points, name), indent=2) + "\n"
        (out / f"{name}.json").write_text(text)
        print(out / f"{name}.json")


if __name__ == "__main__":
    main()
