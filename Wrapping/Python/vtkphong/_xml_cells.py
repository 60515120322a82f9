"""The cells of a VTK XML file (.vtp, .vtu), decoded and checked before VTK's reader builds
them. VTK's XML readers trust the offsets and connectivity they decode: a polygon cut to
fewer points than its type needs, an empty cell in appended data (raw or zlib), offsets
that run backwards or past the connectivity, or a point id the piece lacks crash the
reader or what draws its output (SIGSEGV, issue 28).

Decoded here: ascii, inline binary (base64) and appended data (raw or base64), without
compression or with zlib or lzma, UInt32 or UInt64 headers, either byte order. LZ4 has no
decoder in Python's standard library: such files go to VTK's reader unchecked (docs/io.md).
"""

import base64
import lzma
import re
import zlib
import xml.etree.ElementTree as ElementTree

import numpy

from vtkphong._legacy_cells import check_offsets, check_ids
from vtkphong._errors import ReadFailure

NUMPY_TYPES = {"Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4",
               "UInt32": "u4", "Int64": "i8", "UInt64": "u8"}
DECOMPRESS = {"vtkZLibDataCompressor": zlib.decompress, "vtkLZMADataCompressor": lzma.decompress}
# VTK's fixed-size cell types and their point counts; polygons and the like need at least.
FIXED_SIZES = {1: 1, 3: 2, 5: 3, 8: 4, 9: 4, 10: 4, 11: 8, 12: 8, 13: 6, 14: 5}
LEAST_SIZES = {2: 1, 4: 2, 6: 3, 7: 3}
POLYDATA_LEAST = {"Verts": 1, "Lines": 2, "Strips": 3, "Polys": 3}


def check_xml_cells(path):
    """Refuse (ReadFailure) a piece whose cells cannot be built from its arrays."""
    with open(path, "rb") as stream:
        data = stream.read()
    appended = data.find(b"<AppendedData")
    try:
        root = ElementTree.fromstring(data if appended < 0 else data[:appended] + b"</VTKFile>")
    except ElementTree.ParseError as error:
        raise ReadFailure("its XML is not well formed (%s)" % error) from None
    decoder = _Decoder(root, data, appended)
    if decoder.compressor and decoder.compressor not in DECOMPRESS:
        return
    for piece in root.iter("Piece"):
        points = int(piece.get("NumberOfPoints", "0"))
        if root.get("type") == "PolyData":
            for section, least in POLYDATA_LEAST.items():
                cells = piece.find(section)
                if cells is not None:
                    _check_section(decoder, cells, section, points, least)
        elif root.get("type") == "UnstructuredGrid" and piece.find("Cells") is not None:
            _check_section(decoder, piece.find("Cells"), "Cells", points, 0)


def _check_section(decoder, cells, section, points, least):
    arrays = {array.get("Name"): array for array in cells.iter("DataArray")}
    if "connectivity" not in arrays or "offsets" not in arrays:
        return
    connectivity = decoder.values(arrays["connectivity"])
    offsets = numpy.concatenate(([0], decoder.values(arrays["offsets"])))
    check_offsets(section, offsets, connectivity.size)
    check_ids(section, connectivity, points)
    sizes = numpy.diff(offsets)
    if least and sizes.size and sizes.min() < least:
        raise ReadFailure("its %s hold a cell of %d points; each needs %d at least"
                          % (section, int(sizes.min()), least))
    if "types" in arrays:
        _check_types(decoder.values(arrays["types"]), sizes)


def _check_types(types, sizes):
    if types.size != sizes.size:
        raise ReadFailure("its Cells have %d types for %d cells" % (types.size, sizes.size))
    for kind, size in FIXED_SIZES.items():
        wrong = (types == kind) & (sizes != size)
        if wrong.any():
            raise ReadFailure("a cell of type %d has %d points; that type has %d"
                              % (kind, int(sizes[wrong][0]), size))
    for kind, size in LEAST_SIZES.items():
        wrong = (types == kind) & (sizes < size)
        if wrong.any():
            raise ReadFailure("a cell of type %d has %d points; that type needs %d at least"
                              % (kind, int(sizes[wrong][0]), size))


class _Decoder:
    """DataArray values as int64, in the file's formats."""

    def __init__(self, root, data, appended):
        self.order = ">" if root.get("byte_order") == "BigEndian" else "<"
        self.header = numpy.dtype(self.order + ("u8" if root.get("header_type") == "UInt64"
                                                else "u4"))
        self.compressor = root.get("compressor")
        self.data, self.raw, self.text = data, None, None
        if appended >= 0:
            tag_end = data.find(b">", appended)
            encoding = re.search(rb'encoding="(\w+)"', data[appended:tag_end + 1])
            start = data.find(b"_", tag_end) + 1
            if encoding and encoding.group(1) == b"base64":
                self.text = data[start:]
            else:
                self.raw = memoryview(data)[start:]

    def values(self, array):
        kind = NUMPY_TYPES.get(array.get("type"))
        if kind is None:
            raise ReadFailure("its cell array %r has type %s" % (array.get("Name"),
                                                                 array.get("type")))
        dtype = numpy.dtype(self.order + kind)
        form = array.get("format")
        if form == "ascii":
            try:
                return numpy.array([int(w) for w in (array.text or "").split()], numpy.int64)
            except ValueError:
                raise ReadFailure("its cell array %r holds a value that is not an integer"
                                  % array.get("Name")) from None
        if form == "binary":
            payload = self._base64_block(re.sub(rb"\s", b"", (array.text or "").encode()), 0)
        elif form == "appended" and (self.raw is not None or self.text is not None):
            offset = int(array.get("offset", "0"))
            payload = self._raw_block(offset) if self.raw is not None else \
                self._base64_block(self.text, offset)
        else:
            raise ReadFailure("its cell array %r has format %s" % (array.get("Name"), form))
        return numpy.frombuffer(payload[:len(payload) // dtype.itemsize * dtype.itemsize],
                                dtype).astype(numpy.int64)

    def _block_header(self, read):
        """The header's words, read(start, count) giving its bytes from start on: the data's
        sizes, [total] uncompressed, [blocks, block size, last size, sizes...] compressed."""
        width = self.header.itemsize
        if not self.compressor:
            return [int(numpy.frombuffer(read(0, width), self.header)[0])]
        first = numpy.frombuffer(read(0, 3 * width), self.header).tolist()
        if first[0] > len(self.data):
            raise ReadFailure("a compressed array announces %d blocks" % first[0])
        return first + numpy.frombuffer(read(3 * width, first[0] * width),
                                        self.header).tolist()

    def _raw_block(self, offset):
        def read(start, count):
            piece = bytes(self.raw[offset + start:offset + start + count])
            if len(piece) < count:
                raise ReadFailure("an appended array runs past the end of the file")
            return piece
        header = self._block_header(read)
        start = self.header.itemsize * len(header)
        return self._payload(header, lambda count: read(start, count))

    def _base64_block(self, text, offset):
        """VTK encodes the header as a base64 block of its own (padded) and the data as
        another, or (uncompressed, inline) header and data as one block."""
        width = self.header.itemsize

        def decode(at, count):
            chars = (count + 2) // 3 * 4
            try:
                got = base64.b64decode(bytes(text[at:at + chars]))[:count]
            except ValueError:
                got = b""
            if len(got) < count:
                raise ReadFailure("an array's base64 runs past its end")
            return got
        header = self._block_header(lambda start, count: decode(offset, start + count)[start:])
        size = len(header) * width
        chars = (size + 2) // 3 * 4
        if size % 3 and b"=" not in bytes(text[offset + chars - 2:offset + chars]):
            # One block: the data follows the header inside it.
            return self._payload(header, lambda count: decode(offset, size + count)[size:])
        return self._payload(header, lambda count: decode(offset + chars, count))

    def _payload(self, header, read):
        if not self.compressor:
            return read(header[0])
        blocks, sizes = header[0], header[3:]
        packed = read(sum(sizes))
        out, position = [], 0
        for size in sizes[:blocks]:
            try:
                out.append(DECOMPRESS[self.compressor](packed[position:position + size]))
            except (zlib.error, lzma.LZMAError):
                raise ReadFailure("a compressed array does not decompress") from None
            position += size
        return b"".join(out)
