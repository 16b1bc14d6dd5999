"""The text faults of a report figure, read from the record its PNG carries: figures.png writes
the box of every text the figure draws (tick labels, axis labels, titles, legend entries,
annotations such as a point's "dt=...") into the PNG's text chunk `text-boxes`, in PNG pixels
with the origin at the top left. Shared by test_browser.py (every figure of a rendered page) and
test_report_data.py (figures drawn from synthetic data)."""
import io
import json

from PIL import Image

SLACK = 1.0  # pixels: boxes that share no more than this in either direction only touch


def text_boxes(png):
    """The recorded boxes [[left, top, right, bottom, text]] of a PNG (bytes), its width and
    height; boxes None where the PNG carries no record."""
    with Image.open(io.BytesIO(png)) as picture:
        record = picture.info.get("text-boxes")
        return (json.loads(record) if record is not None else None), picture.width, picture.height


def faults(png):
    """['overlap: "a" / "b"', 'cut by the edge: "c"', ...] for a PNG's recorded text; a PNG
    without a record is a fault of its own."""
    boxes, width, height = text_boxes(png)
    if boxes is None:
        return ["no text-boxes record"]
    found = []
    for i, a in enumerate(boxes):
        if a[0] < -SLACK or a[1] < -SLACK or a[2] > width + SLACK or a[3] > height + SLACK:
            found.append(f"cut by the edge of the {width} x {height} figure: {a[4]!r} at {a[:4]}")
        for b in boxes[i + 1:]:
            if min(a[2], b[2]) - max(a[0], b[0]) > SLACK and min(a[3], b[3]) - max(a[1], b[1]) > SLACK:
                found.append(f"overlap: {a[4]!r} at {a[:4]} / {b[4]!r} at {b[:4]}")
    return found
