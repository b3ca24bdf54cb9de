# Request: the base of a snuffle mat for my dog, cut from 3 mm white acrylic (it goes in the
# dishwasher), 400 x 300 with R20 corners. Fleece strips are knotted through 10 mm holes in a
# honeycomb: 20 mm apart along each row, rows 18 mm apart, every other row shifted half a step,
# 18 holes a row, 12 rows. The holes keep at least 15 mm from the outer edges. Along the bottom
# a 50 mm band with no holes carries the dog's name BISCUIT engraved (filled, bold sans, 28 tall)
# between two engraved paw prints (filled), their centres 150 either side of the middle.

units mm
thickness 3 mm
kerf 0.1 mm

W = 400 mm
H = 300 mm
BAND = 50 mm
D = 10 mm
PITCH = 20 mm
ROW = 18 mm
COLS = 18
ROWS = 12
FIELD_W = (COLS - 1) * PITCH + PITCH / 2 + D     # 360: the widest row and its shifted neighbour
FIELD_H = (ROWS - 1) * ROW + D                   # 208

# a paw print: a pad and four toes, all engraved filled
def paw() -> drawing {
    pad = Ellipse(center=(0, 0), rx=11, ry=9, fill=true)
    t1 = Circle(center=(-13, 11), radius=4.5, fill=true)
    t2 = Circle(center=(-5, 18), radius=4.5, fill=true)
    t3 = Circle(center=(5, 18), radius=4.5, fill=true)
    t4 = Circle(center=(13, 11), radius=4.5, fill=true)
    Rigid(self)
}

solid mat {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=20)
    Fixed(body)

    # the first hole at the field's bottom left; the field centred above the band
    hole knot {
        c = Circle(center=(-FIELD_W / 2 + D / 2, -H / 2 + BAND + (H - BAND - FIELD_H) / 2 + D / 2),
                   diameter=D)
    }
    holes = GridPattern(knot, ROWS, COLS, col_spacing=PITCH, row_spacing=ROW, stagger=true)

    drawing name {
        t = Text("BISCUIT", position=(0, -H / 2 + BAND / 2), size=28, font="sans:Bold",
                 valign="middle", fill=true)
    }
    left_paw = paw()
    right_paw = paw()
    left_paw.bb.center_x == -150 mm
    right_paw.bb.center_x == 150 mm
    AlignCenterY(left_paw, name)
    AlignCenterY(right_paw, name)

    # the request's numbers
    assert body.width == 400 mm and body.height == 300 mm, "400 x 300"
    assert len(holes) == 18 * 12, "18 holes a row, 12 rows"
    assert holes[1].c.center.x - holes[0].c.center.x == 20 mm, "20 along a row"
    assert holes[18].c.center.y - holes[0].c.center.y == 18 mm, "rows 18 apart"
    assert holes[18].c.center.x - holes[0].c.center.x == 10 mm, "every other row half a step"
    assert holes[0].c.bb.left - body.bb.left >= 15 mm, "15 from the left edge"
    assert body.bb.right - holes[35].c.bb.right >= 15 mm, "15 from the right edge"
    assert body.bb.top - holes[215].c.bb.top >= 15 mm, "15 from the top edge"
    assert holes[0].c.bb.bottom - body.bb.bottom >= 50 mm, "no hole in the 50 band"
    assert name.t.position.y - body.bb.bottom == 25 mm, "name in the band's middle"
    assert distance(name, left_paw) >= 5 mm and distance(name, right_paw) >= 5 mm, "paws clear of the name"
}
