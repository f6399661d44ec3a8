"""The printers' own files (.ctb, Anycubic Photon Workshop) judged by readers written from the
public specifications (spec_readers/, not the product's writers): for each preset, a member's
print job by reuse and a plate of 10 members decode layer for layer, pixel for pixel and grey
level for grey level, to the PNG folder of the same printer and job; every header field and
layer definition says what the preset says; a member made by reuse is byte for byte the one made
by direct slicing. Each check is shown to fail on a file with one modelled writer bug.

check_header(path, expect, layers) and check_layers(path, png_folder) raise ValueError naming
the field or layer and the figures; the good files and the broken ones go through the same code.
"""
import json
import re
import struct
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

import slicereuse_pymeshlab as sr
from conftest import THICKNESS
from spec_readers import ctb, photon_workshop as pw
from test_plates import png_pixels

# The presets this suite judges and the file each prints (the presets branch adds them to
# common/printer/presets.json; their figures are read from there).
FORMATS = {
    "elegoo_mars_2_pro": ".ctb",
    "phrozen_sonic_mighty_4k": ".ctb",
    "anycubic_photon_mono_x": ".pwmx",
    "anycubic_photon_mono_x_6k": ".pwmb",
    "anycubic_photon_mono_4": ".pm4n",
    "anycubic_photon_mono_m5s": ".pm5s",
}
PRESETS = {p["id"]: p for p in json.loads(sr.PRESETS.read_text())["presets"]}
# PrinterProfile's defaults (printer_profile.h) for the figures a preset may leave out.
PROFILE_DEFAULTS = {"grey_levels": 256, "file_version": 0,
                    "lift": {"bottom_height_mm": 5, "height_mm": 5, "bottom_speed_mm_min": 65, "speed_mm_min": 65,
                             "bottom_retract_speed_mm_min": 150, "retract_speed_mm_min": 150,
                             "bottom_light_off_s": 0, "light_off_s": 0}}
NEWEST_CTB_VERSION = 4
PLATE_MEMBERS = 10
# The parts' height: 20 layers of THICKNESS, past every preset's 8 bottom layers, and few enough
# for the 12K displays (59 M pixels a layer) to stay cheap.
PART_HEIGHT = 2.0
LAYERS = 20


def f32(x):
    """x as the file's single-precision float holds it."""
    return float(np.float32(x))


@dataclass
class Expect:
    """What a preset's file must say: the mask image's size and the job's figures."""
    printer: str
    extension: str
    width: int
    height: int
    width_mm: float
    height_mm: float
    pixel_um: tuple
    mirror_x: bool
    mirror_y: bool
    grey_levels: int
    model: str
    exposure_s: float
    bottom_exposure_s: float
    bottom_layers: int
    faded_layers: int
    layer_move_s: float
    lift: dict
    file_version: int
    thickness: float

    def layer_exposure_s(self, k):
        """print_estimate.h's layer_exposure_s: bottom layers, then faded layers stepping down."""
        if k < self.bottom_layers:
            return self.bottom_exposure_s
        if k - self.bottom_layers < self.faded_layers:
            return self.bottom_exposure_s + (self.exposure_s - self.bottom_exposure_s) * \
                (k - self.bottom_layers + 1) / (self.faded_layers + 1)
        return self.exposure_s

    def print_seconds(self, layers):
        return layers * self.layer_move_s + sum(self.layer_exposure_s(k) for k in range(layers))

    def bottom(self, k):
        return k < self.bottom_layers

    def light_off_s(self, bottom):
        """The wait after the retract: long enough that the moves and the wait take layer_move_s,
        printer_profile.h's "time between two exposures" that print_seconds counts per layer, and
        at least the profile's light-off (the light stays off that long after the retract)."""
        b = "bottom_" if bottom else ""
        lift = self.lift[f"{b}height_mm"]
        moves_s = 60 * (lift / self.lift[f"{b}speed_mm_min"] + lift / self.lift[f"{b}retract_speed_mm_min"])
        return max(self.lift[f"{b}light_off_s"], self.layer_move_s - moves_s)


def expect_of(printer, thickness=THICKNESS):
    """The figures of presets.json's `printer`; fails, saying so, while the preset is missing."""
    if printer not in PRESETS:
        pytest.fail(f"printer preset '{printer}' is not in common/printer/presets.json (the presets branch adds "
                    f"it); the presets there are: {', '.join(PRESETS)}")
    p = PRESETS[printer]
    d, job = p["display"], p["job"]
    lift = {**PROFILE_DEFAULTS["lift"], **job.get("lift", {})}
    # mask_image_layout: portrait images are height_px wide, their columns along y.
    if d["portrait"]:
        width, height, pixel = d["height_px"], d["width_px"], (d["pixel_y_um"], d["pixel_x_um"])
    else:
        width, height, pixel = d["width_px"], d["height_px"], (d["pixel_x_um"], d["pixel_y_um"])
    return Expect(printer, p["extension"], width, height, width * pixel[0] / 1000, height * pixel[1] / 1000, pixel,
                  d["mirror_x"], d["mirror_y"], d.get("grey_levels", PROFILE_DEFAULTS["grey_levels"]), job["model"],
                  job["exposure_s"], job["bottom_exposure_s"], job["bottom_layers"], job["faded_layers"],
                  job["layer_move_s"], lift, job.get("file_version", PROFILE_DEFAULTS["file_version"]), thickness)


# --- the checks ------------------------------------------------------------------------------
class Mismatches:
    """Collects a file's disagreements with what it should say; raise_any() raises them all in one
    ValueError, each naming the field and both figures."""

    def __init__(self, path):
        self.path, self.found = Path(path), []

    def equal(self, what, got, want):
        if got != want:
            self.found.append(f"{what} is {got!r}, should be {want!r}")

    def close(self, what, got, want, tol=1e-4):
        if abs(got - want) > tol * max(1.0, abs(want)):
            self.found.append(f"{what} is {got!r}, should be {want!r}")

    def raise_any(self):
        if self.found:
            raise ValueError(f"{self.path.name}: " + "; ".join(self.found))


def read_printer_file(path):
    """The spec reader of the file's extension."""
    return ctb.read_ctb(path) if Path(path).suffix.lower() == ".ctb" else pw.read_photon_workshop(path)


def check_header(path, expect, layers):
    """Every header field and layer definition of a .ctb or Photon Workshop file against the
    preset's figures, for a job of `layers` layers of expect.thickness."""
    f = read_printer_file(path)
    m = Mismatches(path)
    e, t = expect, expect.thickness
    lift = e.lift
    if isinstance(f, ctb.CtbFile):
        h = f.header
        m.equal("version", h.version, e.file_version or NEWEST_CTB_VERSION)
        m.equal("resolution", h.resolution, (e.width, e.height))
        m.close("display width (mm)", h.bed_x_mm, f32(e.width_mm))
        m.close("display height (mm)", h.bed_y_mm, f32(e.height_mm))
        if h.bed_z_mm < layers * t:
            m.found.append(f"machine height {h.bed_z_mm} mm is below the job's {layers * t} mm")
        # UVtools: projector type 0 shows the image as it is, 1 mirrored left to right.
        m.equal("projector type (mirror)", h.projector_type, int(e.mirror_x))
        m.equal("layer count", h.layer_count, layers)
        m.close("total height (mm)", h.total_height_mm, f32(layers * t))
        m.close("layer height (mm)", h.layer_height_mm, f32(t))
        m.close("exposure (s)", h.exposure_s, f32(e.exposure_s))
        m.close("bottom exposure (s)", h.bottom_exposure_s, f32(e.bottom_exposure_s))
        m.equal("bottom layers", h.bottom_layers, e.bottom_layers)
        m.equal("print parameters' bottom layers", h.bottom_layers_2, e.bottom_layers)
        m.close("light-off (s)", h.light_off_s, f32(e.light_off_s(False)))
        m.close("print parameters' light-off (s)", h.light_off_s_2, f32(e.light_off_s(False)))
        m.close("bottom light-off (s)", h.bottom_light_off_s, f32(e.light_off_s(True)))
        # Version 4 holds a lift as its total and its second stage (UVtools: total = first + second).
        m.close("bottom lift (mm)", h.bottom_lift_mm, f32(lift["bottom_height_mm"]))
        m.close("lift (mm)", h.lift_mm, f32(lift["height_mm"]))
        m.close("bottom lift speed (mm/min)", h.bottom_lift_speed_mm_min, f32(lift["bottom_speed_mm_min"]))
        m.close("lift speed (mm/min)", h.lift_speed_mm_min, f32(lift["speed_mm_min"]))
        m.close("retract speed (mm/min)", h.retract_speed_mm_min, f32(lift["retract_speed_mm_min"]))
        if h.version >= 4:
            m.close("bottom retract speed (mm/min)", h.v4["bottom_retract_speed_mm_min"],
                    f32(lift["bottom_retract_speed_mm_min"]))
            m.equal("last layer index", h.v4["last_layer_index"], layers - 1)
        m.equal("machine name", h.machine_name, e.model)
        m.equal("transition layers", h.transition_layers, e.faded_layers)
        m.equal("level sets", h.level_set_count, 1)
        m.close("print time (s)", h.print_time_s, round(e.print_seconds(layers)),
                tol=1 / max(1, e.print_seconds(layers)))
        for k, layer in enumerate(f.layers):
            b = e.bottom(k)
            m.close(f"layer {k}'s z (mm)", layer.z_mm, f32((k + 1) * t))
            m.close(f"layer {k}'s exposure (s)", layer.exposure_s, f32(e.layer_exposure_s(k)))
            m.close(f"layer {k}'s light-off (s)", layer.light_off_s, f32(e.light_off_s(b)))
            if layer.ext is not None:
                m.close(f"layer {k}'s lift (mm)", layer.ext["lift_mm"],
                        f32(lift["bottom_height_mm" if b else "height_mm"]))
                m.close(f"layer {k}'s lift speed (mm/min)", layer.ext["lift_speed_mm_min"],
                        f32(lift["bottom_speed_mm_min" if b else "speed_mm_min"]))
                m.close(f"layer {k}'s retract speed (mm/min)", layer.ext["retract_speed_mm_min"],
                        f32(lift["bottom_retract_speed_mm_min" if b else "retract_speed_mm_min"]))
    else:
        h, mark = f.header, f.mark
        versions = pw.VERSIONS_OF_EXTENSION.get(Path(path).suffix.lower(), (516, 517, 518))
        if e.file_version:
            m.equal("version", mark.version, e.file_version)
        elif mark.version not in versions or mark.version < 516:
            m.found.append(f"version is {mark.version}, should be one of {[v for v in versions if v >= 516]} "
                           f"(the versions with the EXTRA and MACHINE tables this extension takes)")
        m.equal("resolution", h.resolution, (e.width, e.height))
        m.close("pixel size (um)", h.pixel_size_um, f32(max(e.pixel_um)))
        m.close("layer height (mm)", h.layer_height_mm, f32(t))
        m.close("exposure (s)", h.exposure_s, f32(e.exposure_s))
        m.close("bottom exposure (s)", h.bottom_exposure_s, f32(e.bottom_exposure_s))
        m.close("bottom layers", h.bottom_layers, e.bottom_layers)
        # UVtools: the wait before cure is the light-off delay; speeds are mm/s.
        m.close("light-off (s)", h.wait_before_cure_s, f32(e.light_off_s(False)))
        m.close("lift (mm)", h.lift_mm, f32(lift["height_mm"]))
        m.close("lift speed (mm/s)", h.lift_speed_mm_s, f32(lift["speed_mm_min"] / 60))
        m.close("retract speed (mm/s)", h.retract_speed_mm_s, f32(lift["retract_speed_mm_min"] / 60))
        m.equal("transition layers", h.transition_layers, e.faded_layers)
        m.close("print time (s)", h.print_time_s, round(e.print_seconds(layers)),
                tol=1 / max(1, e.print_seconds(layers)))
        m.equal("layer count", len(f.layers), layers)
        if mark.version >= 516:
            x = h.extra
            m.close("EXTRA bottom lift, both stages (mm)", x["bottom_lift_mm_1"] + x["bottom_lift_mm_2"],
                    f32(lift["bottom_height_mm"]))
            m.close("EXTRA lift, both stages (mm)", x["lift_mm_1"] + x["lift_mm_2"], f32(lift["height_mm"]))
            m.close("EXTRA bottom lift speed (mm/s)", x["bottom_lift_speed_1_mm_s"],
                    f32(lift["bottom_speed_mm_min"] / 60))
            m.close("EXTRA lift speed (mm/s)", x["lift_speed_1_mm_s"], f32(lift["speed_mm_min"] / 60))
            m.close("EXTRA bottom retract speed (mm/s)", x["bottom_retract_speed_1_mm_s"],
                    f32(lift["bottom_retract_speed_mm_min"] / 60))
            m.close("EXTRA retract speed (mm/s)", x["retract_speed_1_mm_s"], f32(lift["retract_speed_mm_min"] / 60))
            m.equal("machine name", h.machine_name, e.model)
            m.close("machine display width (mm)", h.machine["display_width_mm"], f32(e.width_mm))
            m.close("machine display height (mm)", h.machine["display_height_mm"], f32(e.height_mm))
            if h.machine["machine_z_mm"] < layers * t:
                m.found.append(f"machine height {h.machine['machine_z_mm']} mm is below the job's {layers * t} mm")
            if "resolution_x" in h.machine:
                m.equal("machine resolution", (h.machine["resolution_x"], h.machine["resolution_y"]),
                        (e.width, e.height))
                m.close("machine pixel width (um)", h.machine["pixel_width_um"], f32(e.pixel_um[0]))
                m.close("machine pixel height (um)", h.machine["pixel_height_um"], f32(e.pixel_um[1]))
        z = 0.0
        for k, layer in enumerate(f.layers):
            b = e.bottom(k)
            z += layer.layer_height_mm
            m.close(f"layer {k}'s layer height (mm)", layer.layer_height_mm, f32(t))
            m.close(f"layer {k}'s z, its layer heights summed (mm)", z, (k + 1) * t)
            m.close(f"layer {k}'s exposure (s)", layer.exposure_s, f32(e.layer_exposure_s(k)))
            m.close(f"layer {k}'s lift (mm)", layer.lift_mm, f32(lift["bottom_height_mm" if b else "height_mm"]))
            m.close(f"layer {k}'s lift speed (mm/s)", layer.lift_speed_mm_s,
                    f32(lift["bottom_speed_mm_min" if b else "speed_mm_min"] / 60))
        for k, sub in enumerate(f.sublayers):
            layer = f.layers[k]
            m.equal(f"SUBIMGS layer {k} (address, size, lit pixels)",
                    (sub["data_address"], sub["data_size"], sub["lit_pixels"]),
                    (layer.data_address, layer.data_size, layer.lit_pixels))
    m.raise_any()
    return f


def png_layers(folder):
    """A PNG folder's layer images in order (layerNNNNN.png, docs/formats.md)."""
    names = sorted(Path(folder).glob("layer*.png"), key=lambda p: int(re.search(r"(\d+)\.png$", p.name).group(1)))
    if not names:
        raise ValueError(f"{folder}: no layer PNGs")
    return names


def check_layers(path, png_folder):
    """Every layer of the file decoded by the spec reader equals the PNG of the same layer pixel
    for pixel and grey level for grey level; Anycubic layers' lit-pixel counts are the PNGs'
    non-zero pixels. Returns the number of layers."""
    f = read_printer_file(path)
    name = Path(path).name
    pngs = png_layers(png_folder)
    if len(f.layers) != len(pngs):
        raise ValueError(f"{name}: layer count {len(f.layers)}, the PNG folder has {len(pngs)} layers")
    for k, png in enumerate(pngs):
        want = png_pixels(png.read_bytes())
        try:
            got = f.layer_image(k)
        except ValueError as e:
            raise ValueError(f"{name}: layer {k} does not decode: {e}") from None
        if got.shape != want.shape:
            raise ValueError(f"{name}: layer {k} is {got.shape[1]} x {got.shape[0]} pixels, {png.name} "
                             f"{want.shape[1]} x {want.shape[0]}")
        if not np.array_equal(got, want):
            diff = np.argwhere(got != want)
            r, c = diff[0]
            raise ValueError(f"{name}: layer {k} differs from {png.name} in {len(diff)} pixels, the first at row {r}, "
                             f"column {c}: {got[r, c]} in the file, {want[r, c]} in the PNG")
        if isinstance(f, pw.PwFile):
            lit = int(np.count_nonzero(want))
            if f.layers[k].lit_pixels != lit:
                raise ValueError(f"{name}: layer {k}'s lit-pixel count is {f.layers[k].lit_pixels}, {png.name} has "
                                 f"{lit} non-zero pixels")
    return len(pngs)


# --- the jobs ---------------------------------------------------------------------------------
@dataclass
class Jobs:
    expect: Expect
    member: Path         # a member's file by reuse
    member_direct: Path  # the same member sliced directly (--verify's)
    member_pngs: Path    # the same job as a PNG folder
    plates: list         # [(plate file by reuse, the same plate by direct slicing, its PNG folder)]
    layers: int


@pytest.fixture(scope="module")
def printer_jobs(make_family, tmp_path_factory):
    """printer_jobs(printer) -> Jobs, made once per printer: a family of a small arch, its second
    member's print file by reuse (with verify's direct one) and PNG folder; its members 1..10 on
    plates, each plate's file (by reuse, and direct) and PNG folder."""
    made = {}

    def make(printer):
        if printer not in made:
            expect = expect_of(printer)
            if expect.extension != FORMATS[printer]:
                pytest.fail(f"printer preset '{printer}' prints '{expect.extension}' files, this suite judges "
                            f"'{FORMATS[printer]}'")
            members = make_family("arch", PLATE_MEMBERS + 1, faces=500, height=PART_HEIGHT)
            out = tmp_path_factory.mktemp(printer)
            profile = {"printer": printer, "antialiasing": True}
            job = sr.family(members[0], members[1:2], THICKNESS, out / "files", profile=profile, verify=True,
                            extension=expect.extension)
            pngs = sr.family(members[0], members[1:2], THICKNESS, out / "pngs", profile=profile, extension="")
            for r in (job, pngs):
                assert r["failed"] == 0, r
            t = job["targets"][0]
            assert t["method"] == "reuse" and t["min_similarity"] == 1.0 and t["max_grey_difference"] == 0, t
            member = Path(t["output"])
            if not member.is_file():
                pytest.fail(f"{member.name} is not a file: the product wrote a PNG folder for '{expect.extension}' "
                            f"(no writer of that format)")
            plates = sr.plates(members[0], members[1:], THICKNESS, out / "plates", profile=profile, verify=True,
                               extension=expect.extension)
            assert plates["failed"] == 0 and sum(len(p["members"]) for p in plates["plates"]) == PLATE_MEMBERS, plates
            plate_pngs = sr.plates(members[0], members[1:], THICKNESS, out / "plate_pngs", profile=profile,
                                   extension="", placements=out / "plates" / "plates.json")
            assert plate_pngs["failed"] == 0, plate_pngs
            triples = []
            for p, q in zip(plates["plates"], plate_pngs["plates"]):
                assert all(m["method"] == "reuse" for m in p["members"]), p
                file = out / "plates" / Path(p["output"]).name
                triples.append((file, out / "plates" / "direct" / file.name,
                                out / "plate_pngs" / Path(q["output"]).name))
            made[printer] = Jobs(expect, member, member.with_name(f"{member.stem}.direct{member.suffix}"),
                                 Path(pngs["targets"][0]["output"]), triples, t["layers"])
        return made[printer]

    return make


@pytest.mark.parametrize("printer", list(FORMATS))
def test_print_files_decode_to_the_png_folder_and_say_what_the_preset_says(printer_jobs, printer):
    """A member by reuse and a plate of 10: every layer decodes (spec reader) to the PNG folder of
    the same job, 0 layers differ; the header and layer definitions say the preset's figures; the
    files by reuse are byte for byte those by direct slicing."""
    jobs = printer_jobs(printer)
    assert check_layers(jobs.member, jobs.member_pngs) == jobs.layers == LAYERS
    check_header(jobs.member, jobs.expect, jobs.layers)
    assert jobs.member.read_bytes() == jobs.member_direct.read_bytes()
    assert jobs.plates
    for plate, direct, pngs in jobs.plates:
        layers = check_layers(plate, pngs)
        check_header(plate, jobs.expect, layers)
        assert plate.read_bytes() == direct.read_bytes(), plate
    # The anti-aliased images hold grey levels of the printer's file (the PNGs were quantized to them).
    f = read_printer_file(jobs.member)
    levels = np.flatnonzero(np.bincount(f.layer_image(jobs.layers // 2).ravel(), minlength=256))
    assert len(levels) > 2 and levels[0] == 0 and levels[-1] == 255, levels
    is_ctb = isinstance(f, ctb.CtbFile)
    assert jobs.expect.grey_levels == (128 if is_ctb else 16), "the preset's grey levels are not its file's"
    assert all(v == 0 or (v % 2 == 1 if is_ctb else v % 17 == 0) for v in levels), levels


# --- modelled writer bugs: each check fails on them ------------------------------------------
def encode_rle7(image):
    """A layer as catibo's RLE7 (the spec's encoding, for the modelled bugs): runs of 7-bit codes
    (grey g stored as g >> 1, as Chitubox does), lengths in 1..4 big-endian bytes."""
    codes, lengths = image_runs(image.ravel() >> 1)
    out = bytearray()
    for c, n in zip(codes.tolist(), lengths.tolist()):
        while n:
            run = min(n, (1 << 28) - 1)
            n -= run
            if run == 1:
                out.append(c)
            elif run < 0x80:
                out += bytes([c | 0x80, run])
            elif run < 0x4000:
                out += bytes([c | 0x80, 0x80 | run >> 8, run & 0xFF])
            elif run < 0x200000:
                out += bytes([c | 0x80, 0xC0 | run >> 16, run >> 8 & 0xFF, run & 0xFF])
            else:
                out += bytes([c | 0x80, 0xE0 | run >> 24, run >> 16 & 0xFF, run >> 8 & 0xFF, run & 0xFF])
    return bytes(out)


def encode_pw0(image):
    """A layer as pw0Img (the spec's encoding, for the modelled bugs): level g // 17."""
    levels, lengths = image_runs(image.ravel() // 17)
    out = bytearray()
    for v, n in zip(levels.tolist(), lengths.tolist()):
        limit = 0xFFF if v in (0, 15) else 0xF
        while n:
            run = min(n, limit)
            n -= run
            out += bytes([v << 4 | run >> 8, run & 0xFF]) if v in (0, 15) else bytes([v << 4 | run])
    return bytes(out)


def image_runs(values):
    starts = np.flatnonzero(np.r_[True, values[1:] != values[:-1]])
    return values[starts], np.diff(np.r_[starts, len(values)])


def put(data, offset, fmt, *values):
    struct.pack_into(fmt, data, offset, *values)


def replace_layer_data(path, k, image):
    """Writes `image` as layer k's data (encoded, and for a .ctb encrypted with the header's key
    under layer k's index) at the end of the file and points layer k's definition at it: a writer
    that put the wrong image there."""
    f = read_printer_file(path)
    data = bytearray(f.data)
    at = len(data)
    if isinstance(f, ctb.CtbFile):
        plain = encode_rle7(image)
        stored = ctb.keystream_xor(plain, f.header.encryption_key, k)
        entry = f.header.layer_table_offset + k * ctb.LAYER_DEF.size
        old = ctb.LAYER_DEF.unpack_from(data, entry)
        if f.layers[k].ext is not None:
            at += ctb.LAYER_DEF_EX_SIZE
        new = (*old[:3], at, len(stored), 0, *old[6:])
        put(data, entry, "<3f6I", *new)
        if f.layers[k].ext is not None:
            ext = list(f.layers[k].ext.values())
            ext[0] = ctb.LAYER_DEF_EX_SIZE + len(stored)
            data += ctb.LAYER_DEF.pack(*new) + ctb.LAYER_DEF_EX.pack(*ext)
        data += stored
    else:
        stored = encode_pw0(image)
        put(data, f.mark.layer_definition_address + 20 + k * pw.LAYER_DEF.size, "<2I", at, len(stored))
        if f.sublayers:
            put(data, f.mark.sublayer_definition_address + 24 + k * pw.SUBLAYER_DEF.size, "<2I", at, len(stored))
        data += stored
    Path(path).write_bytes(bytes(data))


def grey_layer(f):
    """A layer with grey pixels, and the first grey run's position in the image."""
    for k in range(len(f.layers)):
        image = f.layer_image(k)
        grey = np.flatnonzero((image.ravel() > 0) & (image.ravel() < 255))
        if len(grey):
            return k, image, grey[0]
    raise AssertionError("no grey pixel in any layer")


def header_offsets(f):
    """Where the mutated header fields are (the specifications' layouts)."""
    if isinstance(f, ctb.CtbFile):
        return {"layer height": (32, "<f"), "exposure": (36, "<f"), "resolution": (52, "<I"),
                "layer count": (68, "<I"), "key": (100, "<I")}
    base = f.mark.header_address + 16
    return {"layer height": (base + 4, "<f"), "exposure": (base + 8, "<f"), "resolution": (base + 44, "<I"),
            "layer count": (f.mark.layer_definition_address + 16, "<I")}


def bump(path, field, change):
    f = read_printer_file(path)
    offset, fmt = header_offsets(f)[field]
    data = bytearray(f.data)
    value, = struct.unpack_from(fmt, data, offset)
    put(data, offset, fmt, change(value))
    Path(path).write_bytes(bytes(data))


def differing_pair(f):
    """Two layers whose images differ (neighbours may be equal in an x-y family member)."""
    images = [f.layer_image(k) for k in range(len(f.layers))]
    a = len(images) // 2
    b = next(k for k in [*range(a + 1, len(images)), *range(a)] if not np.array_equal(images[k], images[a]))
    return a, b, images


def swap_two_layers(path, f):
    a, b, images = differing_pair(f)
    replace_layer_data(path, a, images[b])
    replace_layer_data(path, b, images[a])
    return rf"layer {a} differs from layer{a:05d}\.png in \d+ pixels"


def mirror_one_layer(path, f):
    """A layer written mirrored left to right (or, where that is the same image, top to bottom)."""
    for k in range(len(f.layers)):
        image = f.layer_image(k)
        for flipped in (image[:, ::-1], image[::-1, :]):
            if not np.array_equal(flipped, image):
                replace_layer_data(path, k, flipped)
                return rf"layer {k} differs from layer{k:05d}\.png"
    raise AssertionError("every layer is its own mirror image")


def header_bug(field, change, message):
    def model(path, f):
        bump(path, field, change)
        return message
    return model


# name: (the broken writer, returning what the message must say; the check that catches it)
BUGS = {
    "exposure off": (header_bug("exposure", lambda v: v + 0.5, r"(?<!bottom )exposure \(s\) is [\d.]+, should be"),
                     "header"),
    "resolution off": (header_bug("resolution", lambda v: v + 8, r"resolution is \(\d+, \d+\), should be"), "header"),
    "layer count off": (header_bug("layer count", lambda v: v - 1,
                                   rf"layer count is {LAYERS - 1}, should be {LAYERS}"
                                   rf"|LAYERDEF table's length is \d+; {LAYERS - 1} layers"),
                        "header"),
    "layer height off": (header_bug("layer height", lambda v: v * 2, r"layer height \(mm\) is 0\.2"), "header"),
    "two layers swapped": (swap_two_layers, "layers"),
    "mirrored image": (mirror_one_layer, "layers"),
}


def change_one_grey_run(path, f):
    """One grey run written at the next level the file holds."""
    k, image, at = grey_layer(f)
    changed = image.copy().ravel()
    end = at + 1
    while end < changed.size and changed[end] == changed[at]:
        end += 1
    step = 2 if isinstance(f, ctb.CtbFile) else 17
    g = int(changed[at])
    changed[at:end] = g + step if g + step <= 255 else g - step
    replace_layer_data(path, k, changed.reshape(image.shape))
    return rf"layer {k} differs from layer{k:05d}\.png in {end - at} pixels"


def lit_pixels_off_by_one(path, f):
    k = len(f.layers) // 2
    data = bytearray(f.data)
    put(data, f.mark.layer_definition_address + 20 + k * pw.LAYER_DEF.size + 24, "<I", f.layers[k].lit_pixels + 1)
    if f.sublayers:
        put(data, f.mark.sublayer_definition_address + 24 + k * pw.SUBLAYER_DEF.size + 8, "<I",
            f.layers[k].lit_pixels + 1)
    Path(path).write_bytes(bytes(data))
    return rf"layer {k}'s lit-pixel count is \d+, layer{k:05d}\.png has \d+ non-zero pixels"


def wrong_key(path, f):
    """The header's key is not the one the layers were encrypted with (or a key where the layers
    are not encrypted)."""
    bump(path, "key", lambda v: (v + 1) & 0xFFFFFFFF)
    return r"layer 0 (does not decode|differs)"


CTB_BUGS = {**BUGS, "one grey run changed": (change_one_grey_run, "layers"), "wrong key": (wrong_key, "layers")}
PW_BUGS = {**BUGS, "one grey run changed": (change_one_grey_run, "layers"),
           "lit pixels off by one": (lit_pixels_off_by_one, "layers")}
BUG_CASES = [("elegoo_mars_2_pro", b) for b in CTB_BUGS] + [("anycubic_photon_mono_x", b) for b in PW_BUGS]


@pytest.mark.parametrize("printer, bug", BUG_CASES, ids=[f"{p}-{b.replace(' ', '_')}" for p, b in BUG_CASES])
def test_each_check_fails_on_a_modelled_writer_bug(printer_jobs, tmp_path, printer, bug):
    """A good file with one writer bug modelled in it: the check that should catch it raises,
    naming the field or layer; before the bug, the same checks pass."""
    jobs = printer_jobs(printer)
    broken = tmp_path / jobs.member.name
    broken.write_bytes(jobs.member.read_bytes())
    good = read_printer_file(broken)
    check_header(broken, jobs.expect, jobs.layers)
    check_layers(broken, jobs.member_pngs)
    model, check = (CTB_BUGS if isinstance(good, ctb.CtbFile) else PW_BUGS)[bug]
    message = model(broken, good)
    with pytest.raises(ValueError, match=message):
        if check == "header":
            check_header(broken, jobs.expect, jobs.layers)
        else:
            check_layers(broken, jobs.member_pngs)


# --- the readers on other software's files ------------------------------------------------------
FIXTURES = Path(__file__).parent / "spec_readers" / "fixtures"


def test_ctb_reader_reads_a_file_chitubox_made():
    """stairs.ctb (Chitubox 1.6.5.1 for the Elegoo Mars Pro, encrypted, version 3; from
    luizribeiro/mariner's tests, MIT): the figures mariner's own tests read from it, its
    previews, and every one of its 400 layers decrypted and decoded to exactly 1440 x 2560 pixels."""
    f = ctb.read_ctb(FIXTURES / "stairs.ctb")
    h = f.header
    assert (h.version, h.magic, h.layer_count, h.resolution, h.print_time_s) == \
        (3, ctb.MAGIC_CTB, 400, (1440, 2560), 5621)
    assert (h.bed_x_mm, h.bed_y_mm, h.bed_z_mm) == (f32(68.04), f32(120.96), 150.0)
    assert h.total_height_mm == 20.0 and h.layer_height_mm == f32(0.05)
    assert h.machine_name == "ELEGOO MARS Pro" and h.encryption_key != 0
    assert h.software_version == 0x01060501  # 1.6.5.1
    assert [(p.width, p.height) for p in f.previews] == [(400, 300), (200, 125)]
    ends = [layer.data_address + layer.data_size for layer in f.layers]
    assert ends[:5] == [26272, 28057, 29842, 31627, 33412] and ends[-5:] == [822027, 824704, 827383, 830061, 832745]
    lit = [int(np.count_nonzero(f.layer_image(k))) for k in range(h.layer_count)]
    assert min(lit) > 0
    assert all(layer.z_mm == f32(0.05 * (k + 1)) for k, layer in enumerate(f.layers))
    # Chitubox 1.6.5.1 exposes 4 layers at the bottom exposure where its header says 5 bottom layers.
    assert [layer.exposure_s for layer in f.layers[:6]] == [60.0] * 4 + [8.0] * 2


@pytest.mark.parametrize("bug, message", [
    (lambda d: d.__setitem__(slice(0, 4), b"\x19\x00\xfd\x12"), "is a .cbddlp's, not a .ctb's"),
    (lambda d: struct.pack_into("<I", d, 4, 4), "version 4 with magic 0x12fd0086"),
    (lambda d: struct.pack_into("<I", d, 64, len(d) - 100), "the table of 400 layers at offset"),
    (lambda d: struct.pack_into("<I", d, 10087 + 16, 10 ** 6), "layer 0's data at offset"),
    (lambda d: struct.pack_into("<I", d, 100, 1), "layer 0: the runs make"),
])
def test_ctb_reader_refuses_what_the_specification_does_not_allow(tmp_path, bug, message):
    data = bytearray((FIXTURES / "stairs.ctb").read_bytes())
    bug(data)
    (tmp_path / "bad.ctb").write_bytes(bytes(data))
    with pytest.raises(ValueError, match=re.escape(message)):
        f = ctb.read_ctb(tmp_path / "bad.ctb")
        f.layer_image(0)


def pw_bug_cases():
    """(name, the bug on a Photon Workshop file's bytes given its reading, what the reader says)."""
    def at(f, address, fmt, value):
        return lambda d: struct.pack_into(fmt, d, address, value)
    return [
        ("file mark", lambda f: lambda d: d.__setitem__(slice(0, 8), b"ANYCUBIX"), lambda f: "not 'ANYCUBIC'"),
        ("version", lambda f: at(f, 12, "<I", 600), lambda f: "version 600, not one of"),
        ("table count", lambda f: at(f, 16, "<I", f.mark.tables + 1),
         lambda f: f"counts {f.mark.tables + 1} tables; version {f.mark.version} files have {f.mark.tables}"),
        ("header length", lambda f: at(f, f.mark.header_address + 12, "<I", f.header.table_length + 4),
         lambda f: f"the HEADER table's length is {f.header.table_length + 4}"),
        ("machine mark", lambda f: lambda d: d.__setitem__(slice(f.mark.machine_address, f.mark.machine_address + 7),
                                                            b"MACHINX"),
         lambda f: "should begin with the mark 'MACHINE'"),
        ("layer outside the file", lambda f: at(f, f.mark.layer_definition_address + 20, "<I", len(f.data)),
         lambda f: "layer 0's data at offset"),
        ("bytes after the image",
         lambda f: at(f, f.mark.layer_definition_address + 24, "<I", f.layers[0].data_size + 1),
         lambda f: "1 bytes after the runs that fill the image"),
    ]


@pytest.mark.parametrize("case", range(len(pw_bug_cases())), ids=[c[0].replace(" ", "_") for c in pw_bug_cases()])
def test_photon_workshop_reader_refuses_what_the_specification_does_not_allow(printer_jobs, tmp_path, case):
    """The Photon Workshop reader on a good .pwmx with one structural fault: it raises, in words."""
    jobs = printer_jobs("anycubic_photon_mono_x")
    good = pw.read_photon_workshop(jobs.member)
    _, bug, message = pw_bug_cases()[case]
    data = bytearray(good.data)
    bug(good)(data)
    (tmp_path / "bad.pwmx").write_bytes(bytes(data))
    with pytest.raises(ValueError, match=re.escape(message(good))):
        pw.read_photon_workshop(tmp_path / "bad.pwmx").layer_image(0)


# --- every way of making a file: supports, plates, a Dask worker -----------------------------
@pytest.mark.parametrize("printer", ["elegoo_mars_2_pro", "anycubic_photon_mono_x"])
def test_supported_plates_made_on_a_dask_worker_decode_to_their_png_folder(make_family, tmp_path, printer):
    """family.py --plates --supports on the embedded Dask cluster (--workers 1): the printer's own
    file of a plate of supported members decodes, header and every layer, to the PNG folder the
    same command makes with --format png."""
    from test_batch import family_py
    expect = expect_of(printer)
    members = make_family("arch", 3, faces=500, height=PART_HEIGHT)
    made = {}
    for fmt in (expect.extension[1:], "png"):
        run = family_py("--workers", "1", "--plates", "--supports", "--printer", printer, "--antialiasing",
                        "--format", fmt, "--layer-thickness", THICKNESS, *members, out=tmp_path / fmt)
        made[fmt] = json.loads(run.stdout)
        assert made[fmt]["failed"] == 0 and made[fmt]["engine"] == "LocalCluster of 1 worker process", made[fmt]
    ours, pngs = made[expect.extension[1:]]["plates"], made["png"]["plates"]
    assert len(ours) == len(pngs) == 1 and all(m.get("support_points", 0) > 0 for m in ours[0]["members"]), ours
    layers = check_layers(ours[0]["output"], pngs[0]["output"])
    check_header(ours[0]["output"], expect, layers)
    assert layers > LAYERS  # the part stands on its supports and pad
