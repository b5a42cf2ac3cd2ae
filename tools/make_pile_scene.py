#!/usr/bin/env python3
"""Writes scenes/pile_50.json: fifty non-convex objects heaped in a 5 x 5 x 2 lattice whose
spacing is below the objects' size, each turned at random and shaken every frame, so every
object presses into several neighbours. Run from the repository root; the output is committed,
this script records how it was made."""
import json

SHAPES = [
    ("bunny", {"mesh": "meshes/bunny.obj", "scale": 0.1}, [0.0, -0.48, 0.0]),
    ("torus", {"generator": "torus", "major_radius": 0.45, "minor_radius": 0.15,
               "major_segments": 32, "minor_segments": 16}, [0.0, 0.0, 0.0]),
    ("gear", {"generator": "gear", "teeth": 12, "module": 0.08, "face_width": 0.3},
     [0.0, 0.0, -0.15]),
    ("chain", {"generator": "chain", "links": 2, "major_radius": 0.3, "minor_radius": 0.08,
               "major_segments": 24, "minor_segments": 12}, [-0.22, 0.0, 0.0]),
    ("funnel", {"mesh": "meshes/funnel.obj", "scale": 1.0}, [0.0, 0.0, 0.0]),
    ("propeller", {"mesh": "meshes/propeller.obj", "scale": 1.0}, [0.0, 0.0, 0.0]),
]
SPACING = [0.8, 0.8, 0.7]


def main():
    objects = []
    k = 0
    for layer in range(2):
        for row in range(5):
            for col in range(5):
                name, shape, centring = SHAPES[k % len(SHAPES)]
                position = [col * SPACING[0], row * SPACING[1], layer * SPACING[2]]
                objects.append({
                    "name": f"{name}_{k:02d}",
                    "shape": shape,
                    "pose": {"translation": [p + c for p, c in zip(position, centring)],
                             "rotation": {"axis": [1, 2, 3], "degrees": 37 * k}},
                    "motion": {"jitter": {"seed": 1000 + k, "translation": 0.08,
                                          "rotation_deg": 180}},
                })
                k += 1
    scene = {
        "name": "pile_50",
        "description": (
            "A pile of 50 non-convex objects (bunnies, tori, gears, two-link chains, funnels, "
            "propellers; 500 to 3,700 triangles each, about 1 unit across) in a 5 x 5 x 2 "
            "lattice 0.8 / 0.7 apart, each turned at random and shaken by up to 0.08 every "
            "frame: every object presses into several neighbours. One group query: all "
            "intersecting triangle pairs of every object pair that the shared broad phase "
            "passes (made by tools/make_pile_scene.py)."),
        "frames": 6,
        "objects": objects,
        "queries": [{"name": "all_pairs", "among": "*", "kind": "all_pairs"}],
    }
    with open("scenes/pile_50.json", "w") as out:
        json.dump(scene, out, indent=1)
        out.write("\n")


if __name__ == "__main__":
    main()
