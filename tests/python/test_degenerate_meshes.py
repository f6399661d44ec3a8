"""Broken meshes through the slice filter in pymeshlab: the result names what was found (and
open contours come only with a defect), a mesh between two planes gives no contours, and
non-finite vertices or an absurd layer count are refused with a message in words."""
import numpy as np

from conftest import raises_filter_error


def _box(n=4):
    """A closed unit box, each side split into n x n quads, via pymeshlab's own cube."""
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.create_cube(size=1.0)
    ms.meshing_surface_subdivision_midpoint(iterations=2)
    m = ms.current_mesh()
    return m.vertex_matrix().copy(), m.face_matrix().copy()


DEFECTS = ("duplicate_faces", "zero_area_faces", "repeated_vertex_faces", "boundary_edges", "non_manifold_edges")


def _defects(r):
    """The slice result's five defect counts, by name."""
    return {k: r[k] for k in DEFECTS}


def _counts(**nonzero):
    """Expected defect counts: the ones named, all others 0."""
    return {k: nonzero.get(k, 0) for k in DEFECTS}


def _edges(faces):
    """The undirected edges of faces, as sorted vertex pairs."""
    return {tuple(sorted((int(t[j]), int(t[(j + 1) % 3])))) for t in faces for j in range(3)}


def _slice(pymeshlab, v, f, tmp_path, thickness=0.05):
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f))
    return ms, ms.apply_filter("slice_mesh_with_encoding", layer_thickness=thickness,
                               contour_file=str(tmp_path / "s.ctr"), encoding_file="")


def test_clean_box_has_no_defects(pymeshlab, tmp_path):
    v, f = _box()
    _, r = _slice(pymeshlab, v, f, tmp_path)
    assert r["open_contours"] == 0 and r["contours"] == r["layers"] == 20
    assert _defects(r) == _counts()


def test_duplicated_faces_are_counted_with_the_open_contours_they_cause(pymeshlab, tmp_path):
    v, f = _box()
    dup = f[:50][:, [1, 2, 0]]
    _, r = _slice(pymeshlab, v, np.vstack([f, dup]), tmp_path)
    # Every edge of a duplicated face had 2 faces and now has 3 or 4.
    assert _defects(r) == _counts(duplicate_faces=50, non_manifold_edges=len(_edges(f[:50])))
    assert r["open_contours"] > 0


def test_hole_gives_boundary_edges(pymeshlab, tmp_path):
    v, f = _box()
    z = v[f][:, :, 2]
    side = int(np.argmax(z.max(axis=1) > z.min(axis=1)))  # a face the planes cut
    _, r = _slice(pymeshlab, v, np.delete(f, side, axis=0), tmp_path)
    assert _defects(r) == _counts(boundary_edges=3)
    assert r["open_contours"] > 0


def test_repeated_vertex_and_zero_area_faces_are_counted(pymeshlab, tmp_path):
    v, f = _box()
    n = len(v)
    # Beside the box: a face naming vertex n twice (its one edge n - n+1 then has 2 uses, so it
    # is neither a boundary nor a non-manifold edge), and a face on three collinear points (exact
    # in binary: the cross product is exactly 0), whose 3 edges have 1 use each.
    extra_v = [[2, 1, -0.25], [3, 1, 0.25], [2, 0, -0.25], [3, 0, 0], [4, 0, 0.25]]
    extra_f = [[n, n, n + 1], [n + 2, n + 3, n + 4]]
    _, r = _slice(pymeshlab, np.vstack([v, extra_v]), np.vstack([f, extra_f]), tmp_path)
    assert _defects(r) == _counts(repeated_vertex_faces=1, zero_area_faces=1, boundary_edges=3)


def test_mesh_between_two_planes_gives_no_contours(pymeshlab, tmp_path):
    v, f = _box()
    v = v * np.array([1.0, 1.0, 0.01])  # 0.01 mm tall; the one plane at 0.025 mm misses it
    _, r = _slice(pymeshlab, v, f, tmp_path)
    assert (r["layers"], r["contours"], r["points"]) == (1, 0, 0)
    assert _defects(r) == _counts()


def test_non_finite_vertices_are_refused_in_words(pymeshlab, tmp_path):
    v, f = _box()
    v[7, 2] = np.nan
    v[9, 0] = np.inf
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f))
    raises_filter_error(pymeshlab, ms, "slice_mesh_with_encoding",
                        "the mesh has 2 vertices with NaN or infinite coordinates (first: vertex 7)",
                        layer_thickness=0.05, contour_file=str(tmp_path / "s.ctr"), encoding_file="")
    assert not (tmp_path / "s.ctr").exists()


def test_extreme_coordinates_give_the_layer_count_not_bad_alloc(pymeshlab, tmp_path):
    v, f = _box()
    v = v * 1e6
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f))
    raises_filter_error(pymeshlab, ms, "slice_mesh_with_encoding",
                        "a layer thickness of 0.05 mm gives 2e+07 layers over the part's 1e+06 mm, more "
                        "than the limit of 10000000", layer_thickness=0.05,
                        contour_file=str(tmp_path / "s.ctr"), encoding_file="")
