"""PyVista scenes, in PyVista's own API, for TestPhongClients.py.

    python3 pyvista_scenes.py SCENE OUT.png

draws SCENE off screen (400x300, fixed camera), writes its screenshot to OUT.png and prints
one line per actor, "mapper: CLASS" (the polydata mapper inside a vtkDataSetMapper after
'>'), "budget: MODE" where that mapper has an error budget's mode, and for VTK's composite
mapper "delegator: CLASS", the block drawer VTK's factory hands it. Nothing here names vtkPhong: the driver runs this file once as it is and once after
`import vtkphong.overrides`.
"""

import sys

import numpy as np
import pyvista as pv
from pyvista import examples

SIZE = (400, 300)
CAMERA = [(3.0, -4.0, 2.5), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)]


def sphere():
    return pv.Sphere(radius=1.0, theta_resolution=48, phi_resolution=48)


def smooth_light_kit():
    """smooth_shading=True under PyVista's default light kit, a highlight."""
    pl = pv.Plotter(off_screen=True, window_size=SIZE)
    pl.add_mesh(sphere(), color="tan", smooth_shading=True, specular=0.6, specular_power=25)
    return pl


def airplane_flat():
    """The airplane that ships with PyVista, flat shaded (add_mesh's default), light kit."""
    pl = pv.Plotter(off_screen=True, window_size=SIZE)
    plane = examples.load_airplane()
    plane.translate(-np.array(plane.center), inplace=True)
    plane.scale(2.0 / plane.length, inplace=True)
    pl.add_mesh(plane, color="lightsteelblue", specular=0.4)
    return pl


def positional_spot_lights():
    """A positional point light and a spot light, both attenuated, on a floor and a sphere."""
    pl = pv.Plotter(off_screen=True, window_size=SIZE, lighting="none")
    pl.add_mesh(pv.Plane(center=(0, 0, -1), i_size=6, j_size=6, i_resolution=60,
                         j_resolution=60), color="white", smooth_shading=True)
    pl.add_mesh(sphere(), color="orange", smooth_shading=True, specular=0.5,
                specular_power=30)
    pl.add_light(pv.Light(position=(2.0, -2.0, 2.0), focal_point=(0, 0, 0), color="white",
                          positional=True, cone_angle=90, attenuation_values=(1.0, 0.1, 0.0)))
    pl.add_light(pv.Light(position=(-2.0, -1.0, 3.0), focal_point=(0, 0, -1), color="cyan",
                          positional=True, cone_angle=30, exponent=5,
                          attenuation_values=(0.5, 0.0, 0.05)))
    return pl


def multiblock():
    """A MultiBlock of three meshes, each block its colour (add_composite)."""
    blocks = pv.MultiBlock([sphere().translate((-1.5, 0, 0)), pv.Cube(),
                            pv.Cylinder(center=(1.5, 0, 0), direction=(0, 0, 1))])
    pl = pv.Plotter(off_screen=True, window_size=SIZE)
    pl.add_composite(blocks, multi_colors=True, smooth_shading=True, specular=0.5)
    return pl


def shadows():
    """enable_shadows(): a sphere over a floor under one scene light."""
    pl = pv.Plotter(off_screen=True, window_size=SIZE, lighting="none")
    pl.add_mesh(pv.Plane(center=(0, 0, -1), i_size=6, j_size=6), color="white")
    pl.add_mesh(sphere(), color="seagreen", smooth_shading=True, specular=0.3)
    pl.add_light(pv.Light(position=(1.0, -1.0, 4.0), focal_point=(0, 0, 0),
                          light_type="scene light", intensity=1.0))
    pl.enable_shadows()
    return pl


def ssao():
    """enable_ssao(): spheres in a box corner."""
    pl = pv.Plotter(off_screen=True, window_size=SIZE)
    pl.add_mesh(pv.Box(bounds=(-2, 2, -2, 2, -1.2, -1)), color="white")
    for x in (-1.0, 0.0, 1.0):
        pl.add_mesh(pv.Sphere(radius=0.5, center=(x, 0.3 * x, -0.7)), color="lightblue",
                    smooth_shading=True)
    pl.enable_ssao(radius=0.5)
    return pl


def points_as_spheres():
    """A point cloud, render_points_as_spheres=True."""
    rng = np.random.default_rng(7)
    cloud = pv.PolyData(rng.uniform(-1.0, 1.0, (300, 3)))
    cloud["height"] = cloud.points[:, 2]
    pl = pv.Plotter(off_screen=True, window_size=SIZE)
    pl.add_mesh(cloud, scalars="height", render_points_as_spheres=True, point_size=14,
                show_scalar_bar=False)
    return pl


def edges():
    """show_edges=True on a smooth sphere."""
    pl = pv.Plotter(off_screen=True, window_size=SIZE)
    pl.add_mesh(pv.Sphere(theta_resolution=20, phi_resolution=20), color="wheat",
                show_edges=True, edge_color="black", smooth_shading=True, specular=0.3)
    return pl


def lighting_off():
    """lighting=False on a mesh coloured by a scalar."""
    mesh = sphere()
    mesh["z"] = mesh.points[:, 2]
    pl = pv.Plotter(off_screen=True, window_size=SIZE)
    pl.add_mesh(mesh, scalars="z", cmap="viridis", lighting=False, show_scalar_bar=False)
    return pl


def no_lights():
    """Plotter(lighting='none'): no light at all, a scalar colour map."""
    mesh = sphere()
    mesh["z"] = mesh.points[:, 2]
    pl = pv.Plotter(off_screen=True, window_size=SIZE, lighting="none")
    pl.add_mesh(mesh, scalars="z", cmap="coolwarm", show_scalar_bar=False)
    return pl


def scalars():
    """A finer sphere coloured by a scalar, smooth_shading=True, PyVista's default light kit
    and material (no specular)."""
    mesh = pv.Sphere(radius=1.0, theta_resolution=128, phi_resolution=128)
    mesh["z"] = mesh.points[:, 2]
    pl = pv.Plotter(off_screen=True, window_size=SIZE)
    pl.add_mesh(mesh, scalars="z", cmap="viridis", smooth_shading=True, show_scalar_bar=False)
    return pl


SCENES = {f.__name__: f for f in (smooth_light_kit, airplane_flat, positional_spot_lights,
                                  multiblock, shadows, ssao, points_as_spheres, edges,
                                  lighting_off, no_lights, scalars)}


def report(renderer):
    """The class of every actor's mapper (and its budget's mode), as the driver reads it."""
    from vtkmodules.vtkCommonCore import vtkObjectFactory
    composite = False
    for actor in renderer.actors.values():
        mapper = actor.GetMapper() if hasattr(actor, "GetMapper") else None  # not light actors
        if mapper is None:
            continue
        name = mapper.GetClassName()
        inner = mapper.GetPolyDataMapper() if hasattr(mapper, "GetPolyDataMapper") else None
        if inner is not None:
            name += ">" + inner.GetClassName()
        composite |= mapper.IsA("vtkCompositePolyDataMapper") == 1
        print("mapper: " + name)
        drawer = inner if inner is not None else mapper
        if hasattr(drawer, "GetBudgetModeAsString"):
            print("budget: " + drawer.GetBudgetModeAsString())
    if composite:
        made = vtkObjectFactory.CreateInstance("vtkCompositePolyDataMapperDelegator")
        print("delegator: " + (made.GetClassName() if made is not None else "none"))


def main():
    scene, png = sys.argv[1], sys.argv[2]
    pl = SCENES[scene]()
    pl.camera_position = CAMERA
    pl.show(auto_close=False)
    pl.render()  # a second frame: what a program settles on after its first
    pl.screenshot(png)
    report(pl.renderer)
    pl.close()


if __name__ == "__main__":
    main()
