"""The cell sections of a legacy VTK file, read and checked against its points before VTK's
reader sees them. VTK 9.1's legacy reader crashes (SIGSEGV) on a cell that names point
4294967295, on a binary cell size of 1e9, and on a file cut inside a cell section; it trusts
every size and id it reads.

Called by vtkphong._readers.check_vtk_legacy_counts once the file's sections are walked
(each cell section's values placed in the file, its counts already checked against the
file's size), so that what is read here is at most what the file holds.
"""

import mmap

import numpy

from vtkphong._errors import ReadFailure

# The legacy format's integer types, big-endian in BINARY files.
INTEGER_TYPES = {"char": "i1", "unsigned_char": "u1", "short": "i2", "unsigned_short": "u2",
                 "int": "i4", "unsigned_int": "u4", "long": "i8", "unsigned_long": "u8",
                 "vtkidtype": "i8", "vtktypeint32": "i4", "vtktypeuint32": "u4",
                 "vtktypeint64": "i8", "vtktypeuint64": "u8"}
ASCII_CHUNK = 1 << 20


def check_cells(path, walk):
    """Refuse (ReadFailure) a cell section whose sizes or offsets do not add up to its values,
    or that names a point outside [0, POINTS)."""
    placed = [s for s in walk.cell_sections if len(s) == 4]
    if not placed:
        return
    with open(path, "rb") as stream:
        data = mmap.mmap(stream.fileno(), 0, access=mmap.ACCESS_READ)
    for section in placed:
        keyword = section[0]
        if walk.version5:
            offsets = _values(data, section[2][1:], walk.binary, keyword + " OFFSETS")
            connectivity = _values(data, section[3][1:], walk.binary, keyword + " CONNECTIVITY")
            check_offsets(keyword, offsets, connectivity.size)
            check_ids(keyword, connectivity, walk.points)
        else:
            cells, size = section[1]
            values = _values(data, (size, section[2], section[3]), walk.binary, keyword)
            check_ids(keyword, _ids_of_sizes(keyword, cells, values), walk.points)


def _values(data, placement, binary, what):
    """The section's values as int64: placement is (count, type, file offset)."""
    count, kind, offset = placement
    if binary:
        dtype = numpy.dtype(">" + INTEGER_TYPES.get(kind.lower(), "i4"))
        if offset + count * dtype.itemsize > len(data):
            raise ReadFailure("its %s section ends past the end of the file" % what)
        return numpy.frombuffer(data, dtype, count, offset).astype(numpy.int64)
    parts, got, position, rest = [], 0, offset, b""
    while got < count and position < len(data):
        text = rest + data[position:position + ASCII_CHUNK]
        position += ASCII_CHUNK
        # A number cut by the chunk's end waits for the next chunk.
        cut = len(text) if position >= len(data) else max(text.rfind(b" "), text.rfind(b"\n")) + 1
        words, rest = text[:cut].split()[:count - got], text[cut:]
        try:
            parts.append(numpy.array([int(w) for w in words], dtype=numpy.int64))
        except (ValueError, OverflowError):
            raise ReadFailure("its %s section holds a value that is not an integer" % what) \
                from None
        got += len(words)
    if got < count:
        raise ReadFailure("its %s section ends after %d of its %d values" % (what, got, count))
    return numpy.concatenate(parts) if parts else numpy.zeros(0, numpy.int64)


def _ids_of_sizes(keyword, cells, values):
    """The point ids of `cells` cells stored as (size, ids...) in values. Every cell the
    same size is checked at once; otherwise cell by cell."""
    if cells == 0:
        return values[:0]
    size = int(values[0])
    if size >= 0 and values.size == cells * (size + 1) and (values[::size + 1] == size).all():
        return values.reshape(cells, size + 1)[:, 1:].ravel()
    is_size = numpy.zeros(values.size, bool)
    position, listed = 0, values.tolist()
    for cell in range(cells):
        n = listed[position] if position < len(listed) else -1
        if n < 0 or position + 1 + n > len(listed):
            raise ReadFailure("its %s section's cell %d announces %d points, past the %d values"
                              " the section holds" % (keyword, cell, n, len(listed)))
        is_size[position] = True
        position += n + 1
    return values[:position][~is_size[:position]]


def check_offsets(keyword, offsets, length):
    if offsets.size == 0 or offsets[0] != 0 or offsets[-1] != length or \
            (numpy.diff(offsets) < 0).any():
        raise ReadFailure("its %s OFFSETS do not run from 0 up to its %d CONNECTIVITY values"
                          % (keyword, length))


def check_ids(keyword, ids, points):
    if ids.size and (ids.min() < 0 or ids.max() >= points):
        bad = int(ids.max()) if ids.max() >= points else int(ids.min())
        raise ReadFailure("its %s section names point %d; the file has %d points"
                          % (keyword, bad, points))
