"""The smallest OpenEXR writer the comparison test needs: one part, scanlines, no compression,
32-bit float R, G and B (the layout of the OpenEXR file format document, "Technical
Introduction to OpenEXR"). Here only so that test_compare.py can give `verity compare` the
very renders it gives verity.compare; no EXR library is among the module's dependencies."""
import struct

import numpy as np


def _attribute(name, kind, data):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data


def write_exr(path, image):
    """Writes an (H, W, 3) array as R, G, B float32."""
    image = np.asarray(image, dtype="<f4")
    height, width, _ = image.shape
    channels = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1)
                        for c in "BGR") + b"\0"  # FLOAT, sorted by name
    window = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2) +
              _attribute("channels", "chlist", channels) +
              _attribute("compression", "compression", b"\0") +
              _attribute("dataWindow", "box2i", window) +
              _attribute("displayWindow", "box2i", window) +
              _attribute("lineOrder", "lineOrder", b"\0") +
              _attribute("pixelAspectRatio", "float", struct.pack("<f", 1)) +
              _attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              _attribute("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0")
    line_bytes = 3 * 4 * width
    first = len(header) + 8 * height
    offsets = struct.pack(f"<{height}Q", *(first + y * (8 + line_bytes) for y in range(height)))
    lines = b"".join(struct.pack("<ii", y, line_bytes) +
                     b"".join(image[y, :, c].tobytes() for c in (2, 1, 0))
                     for y in range(height))
    with open(path, "wb") as f:
        f.write(header + offsets + lines)
