"""PrusaSlicer's side of a comparison: its printers' configurations from its own vendor profiles,
and reading the .sl1 / .sl1s archives it (or we) write. Used by the tests that compare our print
files with PrusaSlicer's (tests/python/test_prusaslicer_sl1.py) and by the benchmarks that run
both (bench/bench_supports.py)."""
import configparser
import re
import struct
import subprocess
import zipfile
import zlib
from pathlib import Path

import numpy as np

VENDOR_PROFILES = Path("/usr/share/PrusaSlicer/profiles/PrusaResearch.ini")
SL1S = "Original Prusa SL1S SPEED"


def vendor_section(ini, section):
    """A PrusaResearch.ini section with what it inherits (parents first, "; "-separated)."""
    kind = section.split(":", 1)[0]
    values = {}
    for parent in filter(None, (p.strip() for p in ini[section].get("inherits", "").split(";"))):
        values.update(vendor_section(ini, f"{kind}:{parent}"))
    values.update({k: v for k, v in ini[section].items() if k != "inherits"})
    return values


def prusaslicer_config(printer, **overrides):
    """The printer preset with its default print and material presets, as the GUI would combine
    them, then the overrides (PrusaSlicer's keys, values as strings)."""
    assert VENDOR_PROFILES.is_file(), f"PrusaSlicer's profiles are missing: {VENDOR_PROFILES}"
    ini = configparser.ConfigParser(interpolation=None, strict=False, delimiters=("=",))
    ini.optionxform = str
    ini.read(VENDOR_PROFILES)
    machine = vendor_section(ini, f"printer:{printer}")
    config = {**vendor_section(ini, f"sla_print:{machine['default_sla_print_profile']}"),
              **vendor_section(ini, f"sla_material:{machine['default_sla_material_profile']}"), **machine}
    for key in list(config):
        if key.startswith(("compatible_", "default_")) or key.endswith("_notes"):
            del config[key]
    config.update(overrides)
    return config


def write_config(path, config):
    """config as an .ini PrusaSlicer's --load reads."""
    Path(path).write_text("".join(f"{k} = {v}\n" for k, v in config.items()))


def png_grey(data, name):
    """An 8-bit greyscale PNG without row filters (what both writers make) as a uint8 array."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", name
    pos, idat, header = 8, b"", None
    while pos < len(data):
        size, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", data[pos + 8:pos + 8 + size])
        elif kind == b"IDAT":
            idat += data[pos + 8:pos + 8 + size]
        pos += 12 + size
    width, height, depth, colour, _, _, interlace = header
    assert (depth, colour, interlace) == (8, 0, 0), f"{name}: not 8-bit greyscale: {header}"
    rows = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, width + 1)
    assert not rows[:, 0].any(), f"{name}: row filters (this reader takes only filter 0)"
    return rows[:, 1:]


def archive_ini(z, name):
    """An archive's "key = value" file (config.ini, prusaslicer.ini) as a dict; a key without a
    value ("key =") maps to ""."""
    return dict(line.split(" = ", 1) if " = " in line else (line.rstrip(" ="), "")
                for line in z.read(name).decode().splitlines())


def read_archive(path):
    """(layer images in order, config.ini dict, prusaslicer.ini dict)."""
    with zipfile.ZipFile(path) as z:
        layers = sorted(n for n in z.namelist() if "/" not in n and re.search(r"\d{5}\.png$", n))
        images = [png_grey(z.read(n), f"{path.name}:{n}") for n in layers]
        return images, archive_ini(z, "config.ini"), archive_ini(z, "prusaslicer.ini")


def archive_height(path):
    """(layer count, layer height in mm) from an archive's config.ini: numSlow + numFast layers of
    layerHeight. Raises ValueError in words when the file is no such archive."""
    try:
        with zipfile.ZipFile(path) as z:
            config = archive_ini(z, "config.ini")
    except (zipfile.BadZipFile, KeyError) as e:
        raise ValueError(f"{path}: not an SL1/SL1S archive with a config.ini ({e})") from None
    try:
        return int(config["numSlow"]) + int(config["numFast"]), float(config["layerHeight"])
    except (KeyError, ValueError) as e:
        raise ValueError(f"{path}: config.ini lacks a readable numSlow, numFast or layerHeight ({e})") from None


def resin_mm3(archive, pixel_mm2, layer_mm):
    """The cured volume of an archive's stack: every layer's grey levels / 255 x pixel area x layer
    height."""
    layers, _, _ = read_archive(archive)
    return sum(float(np.asarray(image, np.float64).sum()) for image in layers) / 255 * pixel_mm2 * layer_mm


def support_resin_mm3(stl, out, layer_height, critical_angle, density_percent, display_px=None, printer=SL1S):
    """PrusaSlicer's supports and pad for the part in stl, in mm3: the cured volume of its
    --export-sla with them (the printer's default print preset, at this layer height, critical
    angle and support point density) minus that without them (nor elephant-foot compensation,
    whose first layer is then the part's). display_px: the display cropped to a square of that many
    pixels (their size kept), so that PrusaSlicer draws fewer. The configurations and archives go
    to the folder out."""
    config = prusaslicer_config(printer, layer_height=f"{layer_height:g}", initial_layer_height=f"{layer_height:g}",
                                support_critical_angle=f"{critical_angle:g}",
                                support_points_density_relative=f"{density_percent:g}")
    pixel_mm = float(config["display_width"]) / int(config["display_pixels_x"]), \
        float(config["display_height"]) / int(config["display_pixels_y"])
    if display_px is not None:
        width, height = display_px * pixel_mm[0], display_px * pixel_mm[1]
        # The bed too: PrusaSlicer centres the part on the bed, the display spans it.
        config.update(display_pixels_x=str(display_px), display_pixels_y=str(display_px),
                      display_width=f"{width:g}", display_height=f"{height:g}",
                      bed_shape=f"0x0,{width:g}x0,{width:g}x{height:g},0x{height:g}")
    pixel_mm2 = pixel_mm[0] * pixel_mm[1]
    volume = {}
    for kind, changes in (("supported", {}),
                          ("alone", {"supports_enable": "0", "pad_enable": "0", "elefant_foot_compensation": "0"})):
        ini, archive = Path(out) / f"{Path(stl).stem}_{kind}.ini", Path(out) / f"{Path(stl).stem}_{kind}.sl1s"
        write_config(ini, {**config, **changes})
        subprocess.run(["prusa-slicer", "--export-sla", "--load", str(ini), "-o", str(archive), str(stl)],
                       check=True, capture_output=True)
        volume[kind] = resin_mm3(archive, pixel_mm2, layer_height)
    return volume["supported"] - volume["alone"]


def stl_z_extent(path):
    """(triangle count, lowest z, highest z) of a binary STL (what PrusaSlicer exports). Raises
    ValueError in words when the file is no binary STL."""
    data = Path(path).read_bytes()
    count = struct.unpack_from("<I", data, 80)[0] if len(data) >= 84 else -1
    if count < 0 or len(data) != 84 + 50 * count:
        raise ValueError(f"{path}: not a binary STL ({len(data)} bytes, header says {count} triangles)")
    if count == 0:
        return 0, 0.0, 0.0
    facets = np.frombuffer(data, np.dtype([("normal", "<3f4"), ("corners", "<3f4", (3,)), ("attr", "<u2")]),
                           count, 84)
    z = facets["corners"][:, :, 2]
    return count, float(z.min()), float(z.max())
