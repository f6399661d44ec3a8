"""The io_encoding plugin in pymeshlab (MeshLab 2025.07, double): contour files open as edge-mesh
layers with per-vertex attributes and save as .ctr/.srb/.cli/.slc. CLI and SLC files are read
back by the small readers below, written from the two specifications (not the plugin's code)."""
import struct

import numpy as np
import pytest

import slicereuse_pymeshlab as sr


def read_cli(path):
    """CLI per the specification: header lines up to $$HEADEREND, then ASCII commands one per
    line or binary long-format commands. Returns (header dict, [(z, [(dir, xy array)])])."""
    data = path.read_bytes()
    end = data.index(b"$$HEADEREND")
    header = {}
    for line in data[:end].decode("ascii").splitlines():
        if line.startswith("$$") and "/" in line:
            key, value = line[2:].split("/", 1)
            header[key] = value
        elif line.startswith("$$"):
            header[line[2:]] = ""
    layers = []
    body = data[end + len(b"$$HEADEREND"):]
    if "BINARY" in header:
        at = 0
        while at < len(body):
            (cmd,) = struct.unpack_from("<H", body, at)
            at += 2
            if cmd == 127:
                layers.append((struct.unpack_from("<f", body, at)[0], []))
                at += 4
            elif cmd == 130:
                _, direction, n = struct.unpack_from("<iii", body, at)
                at += 12
                xy = np.frombuffer(body, "<f4", 2 * n, at).astype(np.float64).reshape(n, 2)
                at += 8 * n
                layers[-1][1].append((direction, xy))
            else:
                raise ValueError(f"unexpected command {cmd}")
        return header, layers
    lines = body.decode("ascii").split()
    assert lines[0] == "$$GEOMETRYSTART" and lines[-1] == "$$GEOMETRYEND"
    for line in lines[1:-1]:
        cmd, params = line.split("/", 1)
        values = params.split(",")
        if cmd == "$$LAYER":
            layers.append((float(values[0]), []))
        elif cmd == "$$POLYLINE":
            n = int(values[2])
            xy = np.array([float(v) for v in values[3:]]).reshape(n, 2)
            layers[-1][1].append((int(values[1]), xy))
        else:
            raise ValueError(f"unexpected command {cmd}")
    return header, layers


def read_slc(path):
    """SLC per the specification: header up to 0D 0A 1A, 256 reserved bytes, sample table,
    layers (z, boundary count, boundaries) until the termination record. Returns
    (header text, sample table, [(z, [xy arrays])], termination z)."""
    data = path.read_bytes()
    end = data.index(b"\r\n\x1a")
    header = data[:end].decode("ascii")
    at = end + 3
    assert data[at:at + 256] == bytes(256)
    at += 256
    entries = data[at]
    at += 1
    table = [struct.unpack_from("<4f", data, at + 16 * i) for i in range(entries)]
    at += 16 * entries
    layers = []
    while True:
        z, count = struct.unpack_from("<fI", data, at)
        at += 8
        if count == 0xFFFFFFFF:
            assert at == len(data)
            return header, table, layers, z
        boundaries = []
        for _ in range(count):
            n, gaps = struct.unpack_from("<II", data, at)
            at += 8
            assert gaps == 0
            boundaries.append(np.frombuffer(data, "<f4", 2 * n, at).astype(np.float64).reshape(n, 2))
            at += 8 * n
        layers.append((z, boundaries))


@pytest.fixture(scope="module")
def sliced(pymeshlab, make_family, tmp_path_factory):
    """A member sliced with encoding into text files: (folder, slice.ctr)."""
    member = make_family("arch", 1)[0]
    out = tmp_path_factory.mktemp("io")
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(member))
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=0.1, contour_file=str(out / "slice.ctr"),
                    encoding_file=str(out / "slice.enc"), file_format=0)
    return out, out / "slice.ctr"


def contours_of(layer):
    """The layer's contours from its per-vertex attributes: [(layer, [points])] in order."""
    xyz = layer.vertex_matrix()
    layer_index = layer.vertex_custom_scalar_attribute_array("layer")
    contour = layer.vertex_custom_scalar_attribute_array("contour")
    starts = np.flatnonzero(np.diff(contour, prepend=-1))
    bounds = list(starts) + [len(contour)]
    return [(int(layer_index[a]), xyz[a:b]) for a, b in zip(bounds[:-1], bounds[1:])]


def test_contour_file_opens_as_layer_with_attributes(pymeshlab, sliced):
    out, ctr = sliced
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(ctr))
    m = ms.current_mesh()
    header = ctr.read_text().splitlines()[3].split()  # "# layers L contours C points P"
    layers, contours, points = int(header[2]), int(header[4]), int(header[6])
    assert m.vertex_number() == points and m.face_number() == 0
    assert m.edge_number() == points  # every contour of a closed part is a loop
    found = contours_of(m)
    assert len(found) == contours
    assert sorted({k for k, _ in found}) == list(range(layers))
    # The encoding beside (slice.enc) is attached: a face id and area coordinates per point, one
    # of them 0 (the point lies on an edge of its face), summing to 1.
    faces = m.vertex_custom_scalar_attribute_array("face")
    area = m.vertex_custom_point_attribute_matrix("area_coordinates")
    assert faces.shape == (points,) and np.all(faces == np.round(faces)) and faces.min() >= 0
    assert np.all((area == 0).sum(axis=1) >= 1)
    assert np.allclose(area.sum(axis=1), 1, atol=1e-12)


def test_round_trip_through_binary_is_exact(pymeshlab, sliced):
    out, ctr = sliced
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(ctr))
    ms.save_current_mesh(str(out / "copy.srb"))
    assert (out / "copy_enc.srb").is_file()
    ms2 = pymeshlab.MeshSet()
    ms2.load_new_mesh(str(out / "copy.srb"))
    ms2.save_current_mesh(str(out / "back.ctr"))
    assert (out / "back.ctr").read_bytes() == ctr.read_bytes()
    assert (out / "back.enc").read_bytes() == (out / "slice.enc").read_bytes()


def test_contour_file_and_encoding_are_saved_both_or_neither(pymeshlab, sliced):
    out, ctr = sliced
    (out / "pair.ctr").write_text("old")
    (out / "pair.enc").mkdir()  # the encoding cannot be written there
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(ctr))
    with pytest.raises(pymeshlab.PyMeshLabException, match=r"pair\.enc': it is a folder"):
        ms.save_current_mesh(str(out / "pair.ctr"))
    assert (out / "pair.ctr").read_text() == "old"  # not replaced without its encoding
    assert (out / "pair.enc").is_dir() and not any((out / "pair.enc").iterdir())
    assert not list(out.glob("pair.*.tmp-*"))  # nothing staged is left
    (out / "pair.enc").rmdir()
    ms.save_current_mesh(str(out / "pair.ctr"))  # a save that succeeds after the error (see README)
    assert (out / "pair.ctr").read_bytes() == ctr.read_bytes()
    assert (out / "pair.enc").read_bytes() == (out / "slice.enc").read_bytes()


@pytest.mark.parametrize("binary", [False, True])
def test_cli_export_matches_the_layer(pymeshlab, sliced, binary):
    out, ctr = sliced
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(ctr))
    m = ms.current_mesh()
    cli = out / f"slice_{int(binary)}.cli"
    ms.save_current_mesh(str(cli), binary=binary)
    header, layers = read_cli(cli)
    assert ("BINARY" in header) == binary and ("ASCII" in header) != binary
    assert header["UNITS"] == "1" and header["VERSION"] == "200"
    found = contours_of(m)
    assert int(header["LAYERS"]) == len(layers) == max(k for k, _ in found) + 1
    polylines = [(z, d, xy) for z, pls in layers for d, xy in pls]
    assert len(polylines) == len(found)
    for (z, direction, xy), (k, pts) in zip(polylines, found):
        # Closed loops repeat their first point; outer loops run counter-clockwise (dir 1).
        assert direction in (0, 1)
        expected = np.vstack([pts[:, :2], pts[:1, :2]])
        if binary:
            expected = expected.astype(np.float32).astype(np.float64)
        assert np.array_equal(xy, expected)
        area = 0.5 * np.sum(xy[:-1, 0] * xy[1:, 1] - xy[1:, 0] * xy[:-1, 1])
        assert (area > 0) == (direction == 1)
        assert z == (np.float32(pts[0, 2]) if binary else pts[0, 2])
    # And it opens again.
    ms.load_new_mesh(str(cli))
    assert ms.current_mesh().vertex_number() == m.vertex_number()


def test_slc_export_matches_the_layer(pymeshlab, sliced):
    out, ctr = sliced
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(ctr))
    found = contours_of(ms.current_mesh())
    ms.save_current_mesh(str(out / "slice.slc"))
    header, table, layers, end_z = read_slc(out / "slice.slc")
    assert header.startswith("-SLCVER 2.0 -UNIT MM -TYPE PART")
    assert len(table) == 1 and table[0][1] == pytest.approx(0.1)
    boundaries = [b for _, bs in layers for b in bs]
    assert len(boundaries) == len(found)
    for b, (_, pts) in zip(boundaries, found):
        assert np.array_equal(b[0], b[-1])
        assert np.array_equal(b[:-1], pts[:, :2].astype(np.float32).astype(np.float64))
    assert end_z == pytest.approx(layers[-1][0] + 0.1, abs=1e-6)


def test_masks_from_the_opened_layer_equal_masks_from_the_file(pymeshlab, sliced):
    out, ctr = sliced
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(ctr))
    a = ms.apply_filter("export_mask_images", contour_file="", output_path=str(out / "masks_layer"))
    b = ms.apply_filter("export_mask_images", contour_file=str(ctr), output_path=str(out / "masks_file"))
    assert a["layers"] == b["layers"] > 0
    c = ms.apply_filter("compare_mask_stacks", stack_a=str(out / "masks_layer"), stack_b=str(out / "masks_file"),
                        report_file="")
    assert c["differing_pixels"] == 0 and c["min_similarity"] == 1.0


def test_bad_files_and_plain_meshes_are_refused(pymeshlab, sliced, make_family):
    out, ctr = sliced
    ms = pymeshlab.MeshSet()
    cut = out / "cut.cli"
    ms.load_new_mesh(str(ctr))
    ms.save_current_mesh(str(out / "whole.cli"), binary=True)
    cut.write_bytes((out / "whole.cli").read_bytes()[:5000])
    with pytest.raises(pymeshlab.PyMeshLabException, match="the file is truncated"):
        ms.load_new_mesh(str(cut))
    ms.load_new_mesh(str(make_family("arch", 1)[0]))
    with pytest.raises(pymeshlab.PyMeshLabException, match="not a contour layer"):
        ms.save_current_mesh(str(out / "plain.ctr"))
    assert not (out / "plain.ctr").exists()
    with pytest.raises(pymeshlab.PyMeshLabException, match="contour_file is empty and the layer is not a contour layer"):
        ms.apply_filter("export_mask_images", contour_file="", output_path=str(out / "masks_plain"))
    ms.load_new_mesh(str(ctr))  # a filter that succeeds after the errors (see README)
    ms.apply_filter("export_mask_images", contour_file="", output_path=str(out / "masks_after"))
