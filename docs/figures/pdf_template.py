"""The pictures of docs/machines.md, "Printed template": the PDF that `aidl render
examples/laser_box.aidl -o box.pdf` writes (one page the drawing's size) and the first page of
`aidl render examples/telephone.aidl -o phone.pdf --page A4` (tiled), rasterised by pdfium
(pypdfium2, which pdfplumber of the test extra brings).

    python docs/figures/pdf_template.py     # writes docs/images/machines/pdf_template*.png
"""
import sys
from pathlib import Path

import pypdfium2 as pdfium

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
import aidl_lang  # noqa: E402

OUT = ROOT / "docs" / "images" / "machines"


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for name, example, page in (("pdf_template", "laser_box", None),
                                ("pdf_template_a4", "telephone", "A4")):
        res = aidl_lang.compile(path=str(ROOT / "examples" / f"{example}.aidl"))
        data = res.encode("pdf", page=page) if page else res.encode("pdf")
        doc = pdfium.PdfDocument(data)
        pg = doc[0]
        scale = 640 / pg.get_width()
        pg.render(scale=scale).to_pil().convert("RGB").save(OUT / f"{name}.png")
        print(f"wrote docs/images/machines/{name}.png ({len(doc)} page(s))")


if __name__ == "__main__":
    main()
