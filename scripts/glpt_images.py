"""Small image readers for the scripts (no third-party modules): 8-bit RGB/RGBA PNG as glpt
writes it, and X window dumps (xwd) of TrueColor windows. Both return (width, height, rgb) with
rgb a bytes object of width*height*3, rows top to bottom."""
import struct
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, width, height, channels = 8, b"", 0, 0, 0
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body[:13])
            if depth != 8 or colour not in (2, 6) or interlace:
                raise ValueError(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs are read")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    if len(raw) < height * (stride + 1):
        raise ValueError(f"{path}: truncated image data")
    out = bytearray()
    previous = bytearray(stride)
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        kind, row = line[0], bytearray(line[1:])
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        if channels == 3:
            out += row
        else:
            for i in range(0, stride, 4):
                out += row[i:i + 3]
        previous = row
    return width, height, bytes(out)


def read_xwd(path):
    data = open(path, "rb").read()
    fields = struct.unpack(">25I", data[:100])
    (header_size, _version, pixmap_format, _depth, width, height, _xoffset, byte_order, _unit,
     _bit_order, _pad, bits_per_pixel, bytes_per_line, _visual_class, red_mask, green_mask,
     blue_mask, _bits_per_rgb, _cmap_entries, ncolors) = fields[:20]
    if pixmap_format != 2 or bits_per_pixel != 32:
        raise ValueError(f"{path}: only 32-bit ZPixmap window dumps are read")
    pos = header_size + 12 * ncolors
    order = "<" if byte_order == 0 else ">"

    def shift(mask):
        return (mask & -mask).bit_length() - 1

    rs, gs, bs = shift(red_mask), shift(green_mask), shift(blue_mask)
    out = bytearray()
    for y in range(height):
        row = data[pos + y * bytes_per_line:pos + y * bytes_per_line + 4 * width]
        for (pixel,) in struct.iter_unpack(order + "I", row):
            out += bytes(((pixel & red_mask) >> rs, (pixel & green_mask) >> gs,
                          (pixel & blue_mask) >> bs))
    return width, height, bytes(out)


def is_flat(rgb):
    """True when every pixel has the same colour."""
    first = rgb[:3]
    return all(rgb[i:i + 3] == first for i in range(0, len(rgb), 3))
