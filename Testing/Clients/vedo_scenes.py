"""vedo scenes, in vedo's own API, for TestPhongClients.py.

    python3 vedo_scenes.py SCENE OUT.png

draws SCENE off screen (400x300, fixed camera), writes its screenshot to OUT.png and prints
one line per actor, "mapper: CLASS" (and "budget: MODE" where the mapper has an error
budget's mode). Nothing here names vtkPhong: the driver runs this file as it is and after
`import vtkphong.overrides`.
"""

import sys

import numpy as np
import vedo

SIZE = (400, 300)
CAMERA = dict(pos=(3.0, -4.0, 2.5), focal_point=(0.0, 0.0, 0.0), viewup=(0.0, 0.0, 1.0))


def default_look():
    """A Cone and a Sphere with vedo's defaults (its own Plotter lighting)."""
    return [vedo.Cone(pos=(-0.8, 0, 0), r=0.6, height=1.5, c="gold"),
            vedo.Sphere(pos=(0.8, 0, 0), r=0.6, c="tomato")]


def glossy():
    """.lighting('glossy') on a torus."""
    return [vedo.Torus(r1=1.0, r2=0.35, res=60).c("steelblue").lighting("glossy")]


def shiny_phong():
    """.phong() and .lighting('shiny') on a sphere."""
    return [vedo.Sphere(r=1.0, res=48).c("lightgreen").lighting("shiny").phong()]


def light():
    """A vedo Light (a positional light aimed at the mesh) beside the default headlight."""
    mesh = vedo.Sphere(r=1.0, res=48).c("white").phong().lighting("glossy")
    lamp = vedo.Light((2.0, -2.0, 2.0), focal_point=(0, 0, 0), c="yellow", intensity=0.8)
    return [mesh, lamp]


def point_cloud():
    """Points of a fixed random cloud, drawn as spheres, and plain ones."""
    rng = np.random.default_rng(7)
    big = vedo.Points(rng.uniform(-1.0, 1.0, (300, 3)), r=12, c="red5")
    big.render_points_as_spheres(True)
    small = vedo.Points(rng.uniform(-1.0, 1.0, (300, 3)) + (0, 0, 0.2), r=4, c="blue5")
    return [big, small]


def edges():
    """.linewidth(1): a mesh with its edges."""
    return [vedo.Sphere(r=1.0, res=16).c("wheat").linewidth(1).lc("black")]


def flat():
    """.flat() on an icosahedron-like sphere."""
    return [vedo.Sphere(r=1.0, res=10, quads=False).c("orchid").flat()]


def scalars():
    """A sphere coloured by a scalar (.cmap), vedo's default lighting."""
    mesh = vedo.Sphere(r=1.0, res=64)
    points = mesh.vertices  # a property from vedo 2024 on, a method before
    mesh.cmap("viridis", np.asarray(points() if callable(points) else points)[:, 2])
    return [mesh]


SCENES = {f.__name__: f for f in (default_look, glossy, shiny_phong, light, point_cloud,
                                  edges, flat, scalars)}


def report(renderer):
    """The class of every actor's mapper, and its error budget's mode where it has one."""
    for actor in renderer.GetActors():
        mapper = actor.GetMapper()
        if mapper is None:
            continue
        print("mapper: " + mapper.GetClassName())
        if hasattr(mapper, "GetBudgetModeAsString"):
            print("budget: " + mapper.GetBudgetModeAsString())


def main():
    scene, png = sys.argv[1], sys.argv[2]
    plt = vedo.Plotter(offscreen=True, size=SIZE)
    plt.show(*SCENES[scene](), camera=dict(CAMERA), interactive=False)
    plt.render()  # a second frame: what a program settles on after its first
    plt.screenshot(png)
    report(plt.renderer)
    plt.close()


if __name__ == "__main__":
    main()
