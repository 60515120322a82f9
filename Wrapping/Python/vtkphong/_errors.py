"""The two ways vtkphong-render fails, told apart by their exit status, and the reading
child's refusal of a file.

Every module of the command raises them and only the command line
(vtkphong.render) turns them into a message and a status, so the scene,
mesh-reading and rendering modules stay usable from scripts.
"""


class UsageError(Exception):
    """Bad options or scene file: exit status 2."""


class RenderError(Exception):
    """The mesh or the image failed: exit status 1."""


class ReadFailure(Exception):
    """The reading child cannot read the file; the message is the reason. Defined here, not
    in vtkphong._readers, which also runs as __main__: its checks' modules raise the one
    class its main() catches."""
