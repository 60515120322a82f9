"""The two ways vtkphong-render fails, told apart by their exit status.

Every module of the command raises them and only the command line
(vtkphong.render) turns them into a message and a status, so the scene,
mesh-reading and rendering modules stay usable from scripts.
"""


class UsageError(Exception):
    """Bad options or scene file: exit status 2."""


class RenderError(Exception):
    """The mesh or the image failed: exit status 1."""
