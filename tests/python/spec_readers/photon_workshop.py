"""Anycubic Photon Workshop reader (.pwmx, .pwmb, .pm4n, .pm5s, .pwma, .pm5, ...) written from the
public specification only: UVtools' AnycubicFile.cs (the file mark and its table addresses per
version 1, 515, 516, 517, 518; the HEADER, PREVIEW, layer image colour table, LAYERDEF, EXTRA,
MACHINE, software, MODEL, SUBIMGS and PREVIEW2 tables; the pw0Img run-length code). Not the
product's writer.

    read_photon_workshop(path) -> PwFile
      .mark        the file mark: version, number of tables, every table's address
      .header      PwHeader: the HEADER table's fields and the other tables' (colour table, extra,
                   machine, software, model) as dicts
      .previews    [PwPreview(width, height, rgb)]: PREVIEW, then PREVIEW2 (version 518)
      .layers      [PwLayer]: each LAYERDEF entry (data address and size, lift, exposure, layer
                   height, lit-pixel count); .sublayers the SUBIMGS entries (version 518)
      .layer_image(k) -> rows x columns uint8: layer k decoded, a 4-bit level c read as 17c
      .layer_runs(k)  -> (levels 0..15, lengths) as stored

Little-endian. Speeds in the file are mm/s. Anything the specification does not allow raises
ValueError in words.
"""
import struct
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

MARK = b"ANYCUBIC"
VERSIONS = (1, 515, 516, 517, 518)
TABLES_OF_VERSION = {1: 4, 515: 5, 516: 8, 517: 9, 518: 11}
HEADER_LENGTH_OF_VERSION = {1: 80, 515: 80, 516: 84, 517: 92, 518: 96}  # without its 16-byte name and length
MACHINE_LENGTHS = (156, 224)  # with its name and length (UVtools: 224 from version 518)
# The extensions and the versions UVtools writes them with (AnycubicFile.GetAvailableVersionsForExtension).
VERSIONS_OF_EXTENSION = {
    ".pwmx": (1, 515, 516), ".pwmo": (1, 515, 516), ".pwms": (1, 515, 516), ".pmsq": (1, 515, 516),
    ".pwma": (515, 516), ".pm3": (515, 516), ".pm3m": (515, 516),
    ".pwmb": (515, 516, 517), ".pmx2": (515, 516, 517), ".pm3r": (515, 516, 517),
    ".pm3n": (517,), ".pm5": (517,), ".px6s": (517,),
    ".pm5s": (518,), ".m5sp": (518,),
}
NAMED = struct.Struct("<12sI")                     # a table's name and length
HEADER_BASE = struct.Struct("<10f3I2f4s4I")         # 80 bytes
LAYER_DEF = struct.Struct("<2I4f2I")                # 32 bytes
SUBLAYER_DEF = struct.Struct("<3I8f")               # 44 bytes
EXTRA = struct.Struct("<I6fI6f")                    # 56 bytes
MACHINE_BASE = struct.Struct("<96s16s2I3f2I")       # 140 bytes after the name and length (to 156)
MACHINE_518 = struct.Struct("<2f8III2H4I")          # 68 more (to 224)
SOFTWARE = struct.Struct("<32sI32s64s32s")           # 164 bytes, its name is the software's
MODEL = struct.Struct("<6fIf")                      # 32 bytes

GREY_OF_LEVEL = (np.arange(16, dtype=np.uint16) * 17).astype(np.uint8)


def _text(raw):
    return raw.split(b"\0", 1)[0].decode("latin-1")


@dataclass
class PwMark:
    version: int
    tables: int
    header_address: int
    software_address: int
    preview_address: int
    colour_table_address: int
    layer_definition_address: int
    extra_address: int
    machine_address: int = 0
    layer_image_address: int = 0
    model_address: int = 0
    sublayer_definition_address: int = 0
    preview2_address: int = 0


@dataclass
class PwHeader:
    table_length: int
    pixel_size_um: float
    layer_height_mm: float
    exposure_s: float
    wait_before_cure_s: float
    bottom_exposure_s: float
    bottom_layers: float            # a float in the file
    lift_mm: float
    lift_speed_mm_s: float
    retract_speed_mm_s: float
    volume_ml: float
    antialiasing: int
    resolution_x: int
    resolution_y: int
    weight_g: float
    price: float
    price_currency: str
    per_layer_settings: int
    print_time_s: int
    transition_layers: int
    transition_layer_type: int
    advanced_mode: int = 0          # table length >= 84
    grey: int = 0                   # >= 86
    blur_level: int = 0             # >= 88
    resin_type: int = 0             # >= 92
    intelligent_mode: int = 0       # >= 96
    colour_table: dict = field(default_factory=dict)
    extra: dict = field(default_factory=dict)
    machine: dict = field(default_factory=dict)
    software: dict = field(default_factory=dict)
    model: dict = field(default_factory=dict)

    @property
    def resolution(self):
        return self.resolution_x, self.resolution_y

    @property
    def machine_name(self):
        return self.machine.get("name", "")


@dataclass
class PwPreview:
    table: str
    width: int
    height: int
    table_length: int
    rgb: np.ndarray
    extra: tuple = ()


@dataclass
class PwLayer:
    index: int
    data_address: int
    data_size: int
    lift_mm: float
    lift_speed_mm_s: float
    exposure_s: float
    layer_height_mm: float
    lit_pixels: int
    padding: int


def rgb565(data, width, height):
    px = np.frombuffer(bytes(data), dtype="<u2").reshape(height, width)
    rgb = np.empty((height, width, 3), dtype=np.uint8)
    rgb[..., 0] = ((px >> 11) & 0x1F) << 3
    rgb[..., 1] = ((px >> 5) & 0x3F) << 2
    rgb[..., 2] = (px & 0x1F) << 3
    return rgb


def decode_pw0(data, pixels, what):
    """pw0Img (UVtools' DecodePW0): a byte's high nibble is the level; 0 and 15 (black and white)
    take a second byte, the run being the low nibble and that byte (12 bits, 1..4095); the levels
    1..14 are one byte, the run its low nibble (1..15). Returns (levels, lengths); they must make
    exactly `pixels`, with no byte left over."""
    levels, lengths = [], []
    i, n, total = 0, len(data), 0
    while i < n:
        b = data[i]
        level = b >> 4
        if level in (0, 15):
            if i + 1 >= n:
                raise ValueError(f"{what}: a {'black' if level == 0 else 'white'} run's second byte is missing "
                                 f"at the end of the data (byte {i})")
            length = ((b & 0x0F) << 8) | data[i + 1]
            i += 2
        else:
            length = b & 0x0F
            i += 1
        if length == 0:
            raise ValueError(f"{what}: a run of length 0 at byte {i - (2 if level in (0, 15) else 1)}")
        levels.append(level)
        lengths.append(length)
        total += length
        if total > pixels:
            raise ValueError(f"{what}: the runs make more than the image's {pixels} pixels (at byte {i} they "
                             f"reach {total})")
        if total == pixels and i < n:
            raise ValueError(f"{what}: {n - i} bytes after the runs that fill the image")
    if total != pixels:
        raise ValueError(f"{what}: the runs make {total} pixels, the image has {pixels}")
    return np.array(levels, dtype=np.uint8), np.array(lengths, dtype=np.int64)


class PwFile:
    def __init__(self, path):
        self.path = Path(path)
        self.data = self.path.read_bytes()
        self.mark = self._read_mark()
        self.header = self._read_header()
        self.previews = self._read_previews()
        self.layers = self._read_layers()
        self.sublayers = self._read_sublayers()

    def _span(self, offset, size, what):
        if offset <= 0 or size < 0 or offset + size > len(self.data):
            raise ValueError(f"{self.path.name}: {what} at offset {offset}, {size} bytes, lies outside the "
                             f"{len(self.data)}-byte file")
        return self.data[offset:offset + size]

    def _named(self, offset, name, what):
        """A table's 12-byte name (checked) and its length."""
        raw_name, length = NAMED.unpack(self._span(offset, NAMED.size, what))
        if _text(raw_name) != name or raw_name[len(name):].strip(b"\0"):
            raise ValueError(f"{self.path.name}: at offset {offset} the {what} should begin with the mark '{name}', "
                             f"it has {raw_name!r}")
        return length

    def _read_mark(self):
        name = self.path.name
        if self.data[:12] != MARK + b"\0" * 4:
            raise ValueError(f"{name}: the file mark is {self.data[:12]!r}, not 'ANYCUBIC' (zero-filled to 12 bytes)")
        if len(self.data) < 20:
            raise ValueError(f"{name}: {len(self.data)} bytes, too short for the file mark")
        version, tables = struct.unpack_from("<2I", self.data, 12)
        if version not in VERSIONS:
            raise ValueError(f"{name}: version {version}, not one of {', '.join(map(str, VERSIONS))}")
        if tables != TABLES_OF_VERSION[version]:
            raise ValueError(f"{name}: the file mark counts {tables} tables; version {version} files have "
                             f"{TABLES_OF_VERSION[version]}")
        count = 7 + (version >= 516) + (version >= 517) + 2 * (version >= 518)
        addresses = struct.unpack_from(f"<{count}I", self.data, 20)
        a = list(addresses[:6])
        if version >= 516:
            a.append(addresses[6])  # machine
            rest = addresses[7:]
        else:
            a.append(0)
            rest = addresses[6:]
        mark = PwMark(version, tables, *a, layer_image_address=rest[0])
        if version >= 517:
            mark.model_address = rest[1]
        if version >= 518:
            mark.sublayer_definition_address, mark.preview2_address = rest[2], rest[3]
        if mark.header_address != 20 + 4 * count:
            raise ValueError(f"{name}: the header is at {mark.header_address}, not right after the "
                             f"{20 + 4 * count}-byte file mark")
        return mark

    def _read_header(self):
        m, name = self.mark, self.path.name
        length = self._named(m.header_address, "HEADER", "header")
        if length != HEADER_LENGTH_OF_VERSION[m.version]:
            raise ValueError(f"{name}: the HEADER table's length is {length}; version {m.version} files have "
                             f"{HEADER_LENGTH_OF_VERSION[m.version]}")
        raw = self._span(m.header_address + NAMED.size, length, "the HEADER table")
        v = list(HEADER_BASE.unpack_from(raw, 0))
        v[15] = _text(v[15])
        h = PwHeader(length, *v)
        if length >= 84:
            h.advanced_mode, = struct.unpack_from("<I", raw, 80)
        if length >= 88:
            h.grey, h.blur_level = struct.unpack_from("<2H", raw, 84)
        if length >= 92:
            h.resin_type, = struct.unpack_from("<I", raw, 88)
        if length >= 96:
            h.intelligent_mode, = struct.unpack_from("<I", raw, 92)
        if h.resolution_x == 0 or h.resolution_y == 0:
            raise ValueError(f"{name}: resolution {h.resolution_x} x {h.resolution_y} has no pixels")
        if m.version >= 515:
            at = m.colour_table_address
            use_full, count = struct.unpack(f"<2I", self._span(at, 8, "the layer image colour table"))
            if count > 256:
                raise ValueError(f"{name}: the layer image colour table has {count} grey levels, more than 256")
            raw = self._span(at + 8, count + 4, "the layer image colour table's levels")
            h.colour_table = {"use_full_greyscale": use_full, "grey_max_count": count,
                              "grey": list(raw[:count]), "unknown": struct.unpack_from("<I", raw, count)[0]}
        if m.version >= 516:
            length = self._named(m.extra_address, "EXTRA", "EXTRA table")
            f = EXTRA.unpack(self._span(m.extra_address + NAMED.size, EXTRA.size, "the EXTRA table"))
            # Field order as UVtools reads it: the bottom moves, then the others.
            h.extra = dict(zip(["bottom_lift_count", "bottom_lift_mm_1", "bottom_lift_speed_1_mm_s",
                                "bottom_retract_speed_2_mm_s", "bottom_lift_mm_2", "bottom_lift_speed_2_mm_s",
                                "bottom_retract_speed_1_mm_s", "lift_count", "lift_mm_1", "lift_speed_1_mm_s",
                                "retract_speed_2_mm_s", "lift_mm_2", "lift_speed_2_mm_s", "retract_speed_1_mm_s"],
                               f))
            h.extra["table_length"] = length
            length = self._named(m.machine_address, "MACHINE", "MACHINE table")
            if length not in MACHINE_LENGTHS:
                raise ValueError(f"{name}: the MACHINE table's length is {length}, not "
                                 f"{' or '.join(map(str, MACHINE_LENGTHS))}")
            raw = self._span(m.machine_address + NAMED.size, length - NAMED.size, "the MACHINE table")
            f = MACHINE_BASE.unpack_from(raw, 0)
            h.machine = dict(zip(["name", "layer_image_format", "max_antialiasing_level", "property_fields",
                                  "display_width_mm", "display_height_mm", "machine_z_mm", "max_file_version",
                                  "machine_background"], f))
            h.machine["name"] = _text(h.machine["name"])
            h.machine["layer_image_format"] = _text(h.machine["layer_image_format"])
            h.machine["table_length"] = length
            if length >= 224:
                f = MACHINE_518.unpack_from(raw, MACHINE_BASE.size)
                h.machine.update(zip(["pixel_width_um", "pixel_height_um"], f[:2]))
                h.machine["padding"] = f[2:10]
                h.machine.update(zip(["display_count", "padding9", "resolution_x", "resolution_y"], f[10:14]))
                h.machine["padding_end"] = f[14:]
            if h.machine["layer_image_format"] != "pw0Img":
                raise ValueError(f"{name}: the machine's layer image format is '{h.machine['layer_image_format']}'; "
                                 f"this reader decodes 'pw0Img'")
        if m.version >= 517:
            f = SOFTWARE.unpack(self._span(m.software_address, SOFTWARE.size, "the software table"))
            if f[1] != SOFTWARE.size:
                raise ValueError(f"{name}: the software table's length is {f[1]}, not {SOFTWARE.size}")
            h.software = {"name": _text(f[0]), "version": _text(f[2]), "os": _text(f[3]), "opengl": _text(f[4])}
            length = self._named(m.model_address, "MODEL", "MODEL table")
            if length != NAMED.size + MODEL.size:
                raise ValueError(f"{name}: the MODEL table's length is {length}, not {NAMED.size + MODEL.size}")
            f = MODEL.unpack(self._span(m.model_address + NAMED.size, MODEL.size, "the MODEL table"))
            h.model = dict(zip(["min_x", "min_y", "min_z", "max_x", "max_y", "max_z", "supports_enabled",
                                "supports_density"], f))
        return h

    def _read_previews(self):
        m, name = self.mark, self.path.name
        previews = []
        if m.preview_address:
            length = self._named(m.preview_address, "PREVIEW", "preview")
            w, x, hgt = struct.unpack("<I4sI", self._span(m.preview_address + NAMED.size, 12, "the preview"))
            if length != NAMED.size + 12 + 2 * w * hgt:
                raise ValueError(f"{name}: the PREVIEW table's length is {length}; a {w} x {hgt} RGB565 preview "
                                 f"makes {NAMED.size + 12 + 2 * w * hgt}")
            data = self._span(m.preview_address + NAMED.size + 12, 2 * w * hgt, "the preview's pixels")
            previews.append(PwPreview("PREVIEW", w, hgt, length, rgb565(data, w, hgt), (_text(x),)))
        if m.version >= 518 and m.preview2_address:
            length = self._named(m.preview2_address, "PREVIEW2", "second preview")
            w, c1, c2, hgt = struct.unpack("<I2HI", self._span(m.preview2_address + NAMED.size, 12,
                                                                "the second preview"))
            if length != NAMED.size + 12 + 2 * w * hgt:
                raise ValueError(f"{name}: the PREVIEW2 table's length is {length}; a {w} x {hgt} RGB565 preview "
                                 f"makes {NAMED.size + 12 + 2 * w * hgt}")
            data = self._span(m.preview2_address + NAMED.size + 12, 2 * w * hgt, "the second preview's pixels")
            previews.append(PwPreview("PREVIEW2", w, hgt, length, rgb565(data, w, hgt), (c1, c2)))
        return previews

    def _read_layers(self):
        m, name = self.mark, self.path.name
        length = self._named(m.layer_definition_address, "LAYERDEF", "layer definitions")
        count, = struct.unpack("<I", self._span(m.layer_definition_address + NAMED.size, 4, "the layer count"))
        if count == 0:
            raise ValueError(f"{name}: no layers (layer count 0)")
        if length != 4 + LAYER_DEF.size * count:
            raise ValueError(f"{name}: the LAYERDEF table's length is {length}; {count} layers make "
                             f"{4 + LAYER_DEF.size * count}")
        table = self._span(m.layer_definition_address + NAMED.size + 4, LAYER_DEF.size * count,
                           f"the {count} layer definitions")
        layers = []
        for k in range(count):
            layer = PwLayer(k, *LAYER_DEF.unpack_from(table, k * LAYER_DEF.size))
            self._span(layer.data_address, layer.data_size, f"layer {k}'s data")
            if layer.data_address < m.layer_image_address:
                raise ValueError(f"{name}: layer {k}'s data at {layer.data_address} lies before the layer images' "
                                 f"address {m.layer_image_address}")
            layers.append(layer)
        return layers

    def _read_sublayers(self):
        m, name = self.mark, self.path.name
        if m.version < 518:
            return []
        length = self._named(m.sublayer_definition_address, "SUBIMGS", "sub-layer definitions")
        count, index = struct.unpack("<2I", self._span(m.sublayer_definition_address + NAMED.size, 8,
                                                       "the SUBIMGS table"))
        if count != len(self.layers) or length != NAMED.size + 8 + SUBLAYER_DEF.size * count:
            need = NAMED.size + 8 + SUBLAYER_DEF.size * len(self.layers)
            raise ValueError(f"{name}: the SUBIMGS table has {count} layers in {length} bytes; the file has "
                             f"{len(self.layers)} layers, which make {need}")
        table = self._span(m.sublayer_definition_address + NAMED.size + 8, SUBLAYER_DEF.size * count, "SUBIMGS")
        subs = []
        for k in range(count):
            f = SUBLAYER_DEF.unpack_from(table, k * SUBLAYER_DEF.size)
            subs.append({"data_address": f[0], "data_size": f[1], "lit_pixels": f[2], "padding": f[3:],
                         "index": index})
        return subs

    def layer_bytes(self, k):
        layer = self.layers[k]
        return self.data[layer.data_address:layer.data_address + layer.data_size]

    def layer_runs(self, k):
        if not 0 <= k < len(self.layers):
            raise ValueError(f"{self.path.name}: no layer {k} (the file has {len(self.layers)})")
        return decode_pw0(self.layer_bytes(k), self.header.resolution_x * self.header.resolution_y,
                          f"{self.path.name}: layer {k}")

    def layer_image(self, k):
        levels, lengths = self.layer_runs(k)
        return np.repeat(GREY_OF_LEVEL[levels], lengths).reshape(self.header.resolution_y, self.header.resolution_x)


def read_photon_workshop(path):
    return PwFile(path)
