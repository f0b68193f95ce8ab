"""Hand-made inputs of analysis/ncube/accuracy.py for the tests: a solution mesh in
./simulate's layout and a reference file."""
import struct


def ply_bytes(faces):
    """A mesh in ./simulate's layout (solution_mesh.h): faces (patch, element, r, g, b), each
    a triangle of its own three vertices."""
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
              "property double x\nproperty double y\nproperty double z\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\n"
              "property double radiosity_r\nproperty double radiosity_g\nproperty double radiosity_b\n"
              "element face %d\nproperty list uchar int vertex_indices\nproperty int patch\n"
              "property int element\nproperty double radiosity_r\nproperty double radiosity_g\n"
              "property double radiosity_b\nend_header\n") % (3 * len(faces), len(faces))
    out = header.encode()
    for k in range(len(faces)):
        for corner in ((0, 0, k), (1, 0, k), (0, 1, k)):
            out += struct.pack("<dddBBBddd", *corner, 0, 0, 0, 0.0, 0.0, 0.0)
    for k, (patch, element, r, g, b) in enumerate(faces):
        out += struct.pack("<B3iiiddd", 3, 3 * k, 3 * k + 1, 3 * k + 2, patch, element, r, g, b)
    return out


def reference(elements):
    return {"reference_file_version": 1, "self_agreement": {"element_rms": 0.0},
            "elements": elements}
