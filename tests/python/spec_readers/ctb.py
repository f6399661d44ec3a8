"""Chitubox .ctb reader written from the public specifications only:
cbiffle/catibo's doc/cbddlp-ctb.adoc (header, ExtConfig, ExtConfig2, previews, layer table, the
7-bit RLE and the "86" cipher) and UVtools' ChituboxFile.cs (versions 3 and 4: the magic
0x12FD0106 of version 4, the slicer info's transition layers and version-4 table, the 84-byte
layer definition copy before each layer's data). Not the product's writer.

    read_ctb(path) -> CtbFile
      .header      CtbHeader: every field of the file header, print parameters, slicer info,
                   machine name and (version 4) the version-4 print parameters
      .previews    [CtbPreview(width, height, rgb)]: large, then small (rgb: h x w x 3 uint8)
      .layers      [CtbLayer]: each layer table entry (z, exposure, light-off, data address and
                   size, page) and, from version 3, its per-layer copy (lift, retract, ...)
      .layer_image(k) -> h x w uint8: layer k decrypted (key != 0) and decoded, code c read as
                   0 for c = 0 and 2c + 1 otherwise
      .layer_runs(k) -> (codes, lengths): the 7-bit runs as stored

Little-endian throughout except the RLE7 run lengths of more than one byte (big-endian, as the
specification says). Anything the specifications do not allow raises ValueError in words.
"""
import struct
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

MAGIC_CTB = 0x12FD0086      # catibo: ctb (UVtools: versions 2 and 3)
MAGIC_CTB_V4 = 0x12FD0106   # UVtools: version 4 and later
MAGIC_CBDDLP = 0x12FD0019   # catibo: cbddlp, not a .ctb

HEADER = struct.Struct("<II3f2I5f12I2H3I")           # 112 bytes (catibo's file header)
PRINT_PARAMETERS = struct.Struct("<10fI4I")           # 60 bytes (catibo's ExtConfig)
SLICER_INFO = struct.Struct("<7f2IBHBIIIffIIII")      # 76 bytes before the machine name (ExtConfig2)
PRINT_PARAMETERS_V4 = struct.Struct("<ffIfIffffffIIIIIIIIII")  # 84 bytes, then 380 reserved
PRINT_PARAMETERS_V4_RESERVED = 380
PREVIEW = struct.Struct("<4I4I")                     # 32 bytes
LAYER_DEF = struct.Struct("<3f6I")                   # 36 bytes
LAYER_DEF_EX = struct.Struct("<I11f")                 # 48 bytes after the copy of the 36
LAYER_DEF_EX_SIZE = LAYER_DEF.size + LAYER_DEF_EX.size  # 84
PAGE_SIZE = 1 << 32                                   # UVtools: layer data addresses are within 4 GB pages

# catibo's src/crypto.rs and UVtools use 0xD8A83423; the adoc's 0xD8A8_3424 is a typo there.
CIPHER_MUL, CIPHER_ADD = 0x2D83CDAC, 0xD8A83423
IV_MUL, IV_ADD = 0x1E1530CD, 0xEC3D47CD

# The 7-bit level c as Chitubox readers show it: 0 stays 0, else 2c + 1 (3, 5, ..., 255).
GREY_OF_CODE = np.array([0] + [2 * c + 1 for c in range(1, 128)], dtype=np.uint8)


@dataclass
class CtbHeader:
    # file header (offset 0)
    magic: int
    version: int
    bed_x_mm: float
    bed_y_mm: float
    bed_z_mm: float
    unknown1: int
    unknown2: int
    total_height_mm: float
    layer_height_mm: float
    exposure_s: float
    bottom_exposure_s: float
    light_off_s: float
    bottom_layers: int
    resolution_x: int
    resolution_y: int
    large_preview_offset: int
    layer_table_offset: int
    layer_count: int
    small_preview_offset: int
    print_time_s: int
    projector_type: int          # 0 normal, 1 mirrored (LCD printers)
    print_parameters_offset: int
    print_parameters_size: int
    level_set_count: int         # 1 for .ctb (cbddlp's anti-aliasing planes)
    light_pwm: int
    bottom_light_pwm: int
    encryption_key: int
    slicer_info_offset: int
    slicer_info_size: int
    # print parameters (ExtConfig)
    bottom_lift_mm: float = 0.0
    bottom_lift_speed_mm_min: float = 0.0
    lift_mm: float = 0.0
    lift_speed_mm_min: float = 0.0
    retract_speed_mm_min: float = 0.0
    volume_ml: float = 0.0
    weight_g: float = 0.0
    cost: float = 0.0
    bottom_light_off_s: float = 0.0
    light_off_s_2: float = 0.0    # ExtConfig's copy of light_off_s
    bottom_layers_2: int = 0      # ExtConfig's copy of bottom_layers
    print_parameters_padding: tuple = ()
    # slicer info (ExtConfig2)
    bottom_lift_mm_2: float = 0.0
    bottom_lift_speed_2_mm_min: float = 0.0
    lift_mm_2: float = 0.0
    lift_speed_2_mm_min: float = 0.0
    retract_mm_2: float = 0.0
    retract_speed_2_mm_min: float = 0.0
    rest_after_lift_s: float = 0.0
    machine_name_offset: int = 0
    machine_name_size: int = 0
    antialias_flag: int = 0       # UVtools: 7 no AA, 15 AA (catibo's encryption_mode low byte)
    slicer_padding: int = 0
    per_layer_settings: int = 0   # UVtools: 0x10 * version allows per-layer settings
    modified_minutes: int = 0
    antialias_level: int = 0
    software_version: int = 0
    rest_after_retract_s: float = 0.0
    rest_after_lift_s_2: float = 0.0
    transition_layers: int = 0
    print_parameters_v4_offset: int = 0
    slicer_padding_2: tuple = ()
    machine_name: str = ""
    # version 4 print parameters
    v4: dict = field(default_factory=dict)
    disclaimer: str = ""

    @property
    def resolution(self):
        return self.resolution_x, self.resolution_y


@dataclass
class CtbPreview:
    width: int
    height: int
    data_offset: int
    data_size: int
    rgb: np.ndarray


@dataclass
class CtbLayer:
    index: int
    z_mm: float
    exposure_s: float
    light_off_s: float
    data_address: int
    data_size: int
    page: int
    table_size: int
    unknown3: int
    unknown4: int
    ext: dict = None  # version >= 3: the 84-byte per-layer block before the data

    @property
    def file_offset(self):
        return self.page * PAGE_SIZE + self.data_address


def keystream_xor(data, key, layer_index):
    """The "86" cipher (catibo): data XOR the keystream of (key, iv = layer index), 32-bit words
    little-endian, the last word truncated. Its own inverse."""
    if key == 0:
        return bytes(data)
    c = (key * CIPHER_MUL + CIPHER_ADD) & 0xFFFFFFFF
    x0 = (((layer_index * IV_MUL + IV_ADD) & 0xFFFFFFFF) * c) & 0xFFFFFFFF
    words = (len(data) + 3) // 4
    n = np.arange(words, dtype=np.uint64)
    stream = ((np.uint64(x0) + n * np.uint64(c)) & np.uint64(0xFFFFFFFF)).astype("<u4").view(np.uint8)
    return (np.frombuffer(bytes(data), dtype=np.uint8) ^ stream[:len(data)]).tobytes()


def decode_rle7(data, pixels, what):
    """RLE7 (catibo): byte bit 7 = run flag, bits 6..0 the code; a run's length follows in 1..4
    bytes marked by their leading bits (0xxxxxxx, 10xxxxxx +1, 110xxxxx +2, 1110xxxx +3, big-endian).
    Returns (codes, lengths) as numpy arrays; they must make exactly `pixels`."""
    codes, lengths = [], []
    i, n, total = 0, len(data), 0
    while i < n:
        b = data[i]
        i += 1
        length = 1
        if b & 0x80:
            if i >= n:
                raise ValueError(f"{what}: a run's length is missing at the end of the data (byte {i - 1})")
            s = data[i]
            if s & 0x80 == 0:
                extra, length = 0, s
            elif s & 0xC0 == 0x80:
                extra, length = 1, s & 0x3F
            elif s & 0xE0 == 0xC0:
                extra, length = 2, s & 0x1F
            elif s & 0xF0 == 0xE0:
                extra, length = 3, s & 0x0F
            else:
                raise ValueError(f"{what}: run length byte {s:#04x} at byte {i} has no valid length prefix")
            if i + 1 + extra > n:
                raise ValueError(f"{what}: a run's {extra + 1}-byte length runs past the end of the data")
            for j in range(extra):
                length = (length << 8) | data[i + 1 + j]
            i += 1 + extra
            if length == 0:
                raise ValueError(f"{what}: a run of length 0 at byte {i - 2 - extra}")
        codes.append(b & 0x7F)
        lengths.append(length)
        total += length
        if total > pixels:
            raise ValueError(f"{what}: the runs make more than the image's {pixels} pixels "
                             f"(at byte {i} they reach {total})")
    if total != pixels:
        raise ValueError(f"{what}: the runs make {total} pixels, the image has {pixels}")
    return np.array(codes, dtype=np.uint8), np.array(lengths, dtype=np.int64)


def decode_rgb15_rle(data, width, height, what):
    """Preview RLE (catibo's RLE15): u16 little-endian RGB565 with green's low bit (bit 5) the
    run flag; a run's next u16 is 0x3nnn, nnn more copies of the pixel (UVtools' reader and
    writer: the run is 1 + nnn pixels). Must fill width x height exactly."""
    if len(data) % 2:
        raise ValueError(f"{what}: {len(data)} bytes, not whole 16-bit words")
    words = np.frombuffer(bytes(data), dtype="<u2")
    colours, counts = [], []
    k, n = 0, len(words)
    while k < n:
        w = int(words[k])
        k += 1
        count = 1
        if w & 0x20:
            if k >= n:
                raise ValueError(f"{what}: a run's length word is missing at the end")
            r = int(words[k])
            k += 1
            if r & 0xF000 != 0x3000:
                raise ValueError(f"{what}: run length word {r:#06x} is not of the form 0x3nnn")
            count += r & 0x0FFF
        colours.append(w)
        counts.append(count)
    total = sum(counts)
    if total != width * height:
        raise ValueError(f"{what}: the runs make {total} pixels, the {width} x {height} preview has {width * height}")
    px = np.repeat(np.array(colours, dtype=np.uint16), counts)
    rgb = np.empty((height, width, 3), dtype=np.uint8)
    rgb[..., 0] = ((px >> 11) & 0x1F).reshape(height, width) << 3
    rgb[..., 1] = ((px >> 6) & 0x1F).reshape(height, width) << 3
    rgb[..., 2] = (px & 0x1F).reshape(height, width) << 3
    return rgb


class CtbFile:
    def __init__(self, path):
        self.path = Path(path)
        self.data = self.path.read_bytes()
        self.header = self._read_header()
        self.previews = self._read_previews()
        self.layers = self._read_layers()

    # --- structure -------------------------------------------------------------------------
    def _span(self, offset, size, what):
        if offset < 0 or size < 0 or offset + size > len(self.data):
            raise ValueError(f"{self.path.name}: {what} at offset {offset}, {size} bytes, lies outside the "
                             f"{len(self.data)}-byte file")
        return self.data[offset:offset + size]

    def _read_header(self):
        name = self.path.name
        if len(self.data) < HEADER.size:
            raise ValueError(f"{name}: {len(self.data)} bytes, shorter than the {HEADER.size}-byte header")
        v = HEADER.unpack_from(self.data, 0)
        h = CtbHeader(*v)
        if h.magic == MAGIC_CBDDLP:
            raise ValueError(f"{name}: magic {h.magic:#010x} is a .cbddlp's, not a .ctb's")
        if h.magic not in (MAGIC_CTB, MAGIC_CTB_V4):
            raise ValueError(f"{name}: magic {h.magic:#010x} is neither {MAGIC_CTB:#010x} (ctb) nor "
                             f"{MAGIC_CTB_V4:#010x} (ctb version 4)")
        if h.version not in (2, 3, 4):
            raise ValueError(f"{name}: version {h.version}, this reader knows versions 2, 3 and 4")
        expected_magic = MAGIC_CTB_V4 if h.version >= 4 else MAGIC_CTB
        if h.magic != expected_magic:
            raise ValueError(f"{name}: version {h.version} with magic {h.magic:#010x}: version {h.version} "
                             f"files have magic {expected_magic:#010x}")
        if h.level_set_count not in (0, 1):
            raise ValueError(f"{name}: level set count {h.level_set_count}: a .ctb has one image per layer "
                             f"(anti-aliasing is in its 7-bit levels)")
        if h.resolution_x == 0 or h.resolution_y == 0:
            raise ValueError(f"{name}: resolution {h.resolution_x} x {h.resolution_y} has no pixels")
        if h.print_parameters_offset == 0:
            raise ValueError(f"{name}: no print parameters (offset 0)")
        if h.print_parameters_size != PRINT_PARAMETERS.size:
            raise ValueError(f"{name}: print parameters size {h.print_parameters_size}, the table has "
                             f"{PRINT_PARAMETERS.size} bytes")
        p = PRINT_PARAMETERS.unpack(self._span(h.print_parameters_offset, PRINT_PARAMETERS.size,
                                               "the print parameters"))
        (h.bottom_lift_mm, h.bottom_lift_speed_mm_min, h.lift_mm, h.lift_speed_mm_min, h.retract_speed_mm_min,
         h.volume_ml, h.weight_g, h.cost, h.bottom_light_off_s, h.light_off_s_2, h.bottom_layers_2) = p[:11]
        h.print_parameters_padding = p[11:]
        if h.slicer_info_offset == 0:
            raise ValueError(f"{name}: no slicer info (offset 0), which a .ctb of version {h.version} has")
        if h.slicer_info_size < SLICER_INFO.size:
            raise ValueError(f"{name}: slicer info size {h.slicer_info_size}, less than its {SLICER_INFO.size} bytes")
        s = SLICER_INFO.unpack(self._span(h.slicer_info_offset, SLICER_INFO.size, "the slicer info"))
        (h.bottom_lift_mm_2, h.bottom_lift_speed_2_mm_min, h.lift_mm_2, h.lift_speed_2_mm_min, h.retract_mm_2,
         h.retract_speed_2_mm_min, h.rest_after_lift_s, h.machine_name_offset, h.machine_name_size,
         h.antialias_flag, h.slicer_padding, h.per_layer_settings, h.modified_minutes, h.antialias_level,
         h.software_version, h.rest_after_retract_s, h.rest_after_lift_s_2, h.transition_layers,
         h.print_parameters_v4_offset) = s[:19]
        h.slicer_padding_2 = s[19:]
        raw_name = self._span(h.machine_name_offset, h.machine_name_size, "the machine name")
        try:
            h.machine_name = raw_name.decode("utf-8").rstrip("\0")
        except UnicodeDecodeError:
            raise ValueError(f"{name}: the machine name {raw_name!r} is not UTF-8 text") from None
        if h.version >= 4:
            if h.print_parameters_v4_offset == 0:
                raise ValueError(f"{name}: version {h.version} without its version-4 print parameters (offset 0)")
            raw = self._span(h.print_parameters_v4_offset, PRINT_PARAMETERS_V4.size + PRINT_PARAMETERS_V4_RESERVED,
                             "the version-4 print parameters")
            f = PRINT_PARAMETERS_V4.unpack_from(raw, 0)
            keys = ["bottom_retract_speed_mm_min", "bottom_retract_speed_2_mm_min", "padding1", "four1", "padding2",
                    "four2", "rest_after_retract_s", "rest_after_lift_s", "rest_before_lift_s",
                    "bottom_retract_mm_2", "unknown1", "unknown2", "unknown3", "last_layer_index", "padding3",
                    "padding4", "padding5", "padding6", "disclaimer_offset", "disclaimer_size",
                    "resin_parameters_offset"]
            h.v4 = dict(zip(keys, f))
            h.v4["reserved"] = raw[PRINT_PARAMETERS_V4.size:]
            text = self._span(h.v4["disclaimer_offset"], h.v4["disclaimer_size"], "the version-4 disclaimer")
            h.disclaimer = text.decode("utf-8", errors="replace")
        else:
            if h.print_parameters_v4_offset != 0:
                raise ValueError(f"{name}: version {h.version} names version-4 print parameters at "
                                 f"{h.print_parameters_v4_offset}; only version 4 files have them")
        if h.layer_count == 0:
            raise ValueError(f"{name}: no layers (layer count 0)")
        self._span(h.layer_table_offset, h.layer_count * LAYER_DEF.size, f"the table of {h.layer_count} layers")
        return h

    def _read_previews(self):
        previews = []
        for which, offset in (("large", self.header.large_preview_offset), ("small", self.header.small_preview_offset)):
            if offset == 0:
                continue
            w, hgt, data_offset, data_size, *_ = PREVIEW.unpack(self._span(offset, PREVIEW.size,
                                                                           f"the {which} preview's header"))
            data = self._span(data_offset, data_size, f"the {which} preview's data")
            rgb = decode_rgb15_rle(data, w, hgt, f"{self.path.name}: the {which} preview")
            previews.append(CtbPreview(w, hgt, data_offset, data_size, rgb))
        return previews

    def _read_layers(self):
        h, name = self.header, self.path.name
        layers = []
        for k in range(h.layer_count):
            f = LAYER_DEF.unpack_from(self.data, h.layer_table_offset + k * LAYER_DEF.size)
            layer = CtbLayer(k, *f)
            self._span(layer.file_offset, layer.data_size, f"layer {k}'s data")
            if h.version >= 3:
                if layer.table_size != LAYER_DEF_EX_SIZE:
                    raise ValueError(f"{name}: layer {k}'s table size is {layer.table_size}; version {h.version} "
                                     f"layers have {LAYER_DEF_EX_SIZE} (36 + the 48 of the per-layer block)")
                ex_at = layer.file_offset - LAYER_DEF_EX_SIZE
                raw = self._span(ex_at, LAYER_DEF_EX_SIZE, f"layer {k}'s per-layer block before its data")
                copy = LAYER_DEF.unpack_from(raw, 0)
                if copy != f:
                    raise ValueError(f"{name}: layer {k}'s per-layer block at {ex_at} holds {copy}, not the layer "
                                     f"table's entry {f}")
                e = LAYER_DEF_EX.unpack_from(raw, LAYER_DEF.size)
                layer.ext = dict(zip(["total_size", "lift_mm", "lift_speed_mm_min", "lift_mm_2",
                                      "lift_speed_2_mm_min", "retract_speed_mm_min", "retract_mm_2",
                                      "retract_speed_2_mm_min", "rest_before_lift_s", "rest_after_lift_s",
                                      "rest_after_retract_s", "light_pwm"], e))
                if layer.ext["total_size"] != LAYER_DEF_EX_SIZE + layer.data_size:
                    raise ValueError(f"{name}: layer {k}'s per-layer block gives a total size of "
                                     f"{layer.ext['total_size']}, its 84 bytes and {layer.data_size} of data make "
                                     f"{LAYER_DEF_EX_SIZE + layer.data_size}")
            elif layer.table_size not in (0, LAYER_DEF.size):
                raise ValueError(f"{name}: layer {k}'s table size is {layer.table_size}, not {LAYER_DEF.size}")
            layers.append(layer)
        return layers

    # --- images ----------------------------------------------------------------------------
    def layer_bytes(self, k):
        """Layer k's data as stored (encrypted when the key is not 0)."""
        layer = self.layers[k]
        return self.data[layer.file_offset:layer.file_offset + layer.data_size]

    def layer_runs(self, k):
        """Layer k's runs: (7-bit codes, lengths), decrypted."""
        if not 0 <= k < len(self.layers):
            raise ValueError(f"{self.path.name}: no layer {k} (the file has {len(self.layers)})")
        plain = keystream_xor(self.layer_bytes(k), self.header.encryption_key, k)
        return decode_rle7(plain, self.header.resolution_x * self.header.resolution_y,
                           f"{self.path.name}: layer {k}")

    def layer_image(self, k):
        codes, lengths = self.layer_runs(k)
        pixels = np.repeat(GREY_OF_CODE[codes], lengths)
        return pixels.reshape(self.header.resolution_y, self.header.resolution_x)


def read_ctb(path):
    return CtbFile(path)
