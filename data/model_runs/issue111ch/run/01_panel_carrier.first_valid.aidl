# Request (workshop): a panel carrier for walking 8 x 4 ft sheets of plywood and MDF up to
# 19 mm thick round the shop. Glued up from three identical layers of 9 mm birch ply
# (27 mm thick in all). Each layer is a J: a 60 mm wide upright 300 mm tall; at its foot a
# hook whose throat is 22 mm wide (a 19 mm panel plus play) with a 20 mm floor under it and
# a 20 mm wide lip standing 60 mm high from the bottom. At the top a 130 x 70 mm head with
# 20 mm corners holds a horizontal hand hole 100 x 32 mm (rounded ends). Two 8 mm dowel holes
# on the upright's centre line, 45 mm and 215 mm from the bottom, line the layers up in the
# glue-up. Inside corners of the throat rounded 3 mm, the lip's top corners 8 mm. The top
# layer has "MAX 19 mm" engraved up the upright, 8 mm tall letters.

units mm
thickness 9 mm

param height = 300 mm, min = 220 mm, max = 400 mm
param bar_w = 60 mm, min = 50 mm, max = 80 mm
param throat = 22 mm, min = 12 mm, max = 40 mm
param lip_w = 20 mm, min = 15 mm, max = 30 mm
param lip_h = 60 mm, min = 45 mm, max = 90 mm
param floor_h = 20 mm, min = 15 mm, max = 30 mm
param head_w = 130 mm, min = 110 mm, max = 160 mm
param head_h = 70 mm, min = 55 mm, max = 90 mm

def layer(label=false) -> solid {
    bar = Rectangle(bottom_left=(0, 0), width=bar_w, height=height)
    base = Rectangle(bottom_left=(0, 0), width=bar_w + throat + lip_w, height=floor_h)
    lip = Rectangle(bottom_left=(bar_w + throat, 0), width=lip_w, height=lip_h)
    head = RoundedRectangle(center=(bar_w / 2, height - head_h / 2), width=head_w,
                            height=head_h, corner_radius=20)
    hole grip {
        s = Slot(center=(bar_w / 2, height - head_h / 2), length=100, width=32)
    }
    hole dowels {
        for i in range(2) {
            c = Circle(center=(bar_w / 2, 45 + i * 170), diameter=8)
        }
    }
    if label {
        drawing words {
            t = Text("MAX 19 mm", (bar_w / 2, 130), size=8, rotation=90, valign="middle")
        }
    }
    # the throat's inside corners and the head's joins to the upright
    Fillet([bar.right, base.top], 3)
    Fillet([lip.left, base.top], 3)
    Fillet([head.bottom, bar.left], 10)
    Fillet([head.bottom, bar.right], 10)
    # the lip's top corners and the floor's outer corners
    Fillet(lip.top_left, 8)
    Fillet(lip.top_right, 8)
    Fillet(base.bottom_left, 5)
    Fillet(base.bottom_right, 5)
}

assembly carrier {
    bottom = layer()
    middle = layer()
    top = layer(label=true)
    # flat on the sheet side by side
    RightOf(middle, bottom, gap=10)
    RightOf(top, middle, gap=10)
    AlignBottom(middle, bottom)
    AlignBottom(top, bottom)
    # glued up as a stack
    Place(bottom, position=(0, 0, 0))
    Place(middle, position=(0, 0, 9))
    Place(top, position=(0, 0, 18))

    assert top.lip.bb.left - top.bar.bb.right == 22 mm, "throat 22 mm wide"
    assert top.bar.bb.height == 300 mm, "300 mm tall"
    assert top.lip.bb.height == 60 mm, "lip 60 mm high from the bottom"
    assert top.grip.s.length == 100 mm and top.grip.s.width == 32 mm, "hand hole 100 x 32"
    assert top.dowels.c[1].center.y - top.dowels.c[0].center.y == 215 mm - 45 mm, "dowels at 45 and 215"
    assert top.dowels.c[0].center.y - top.bar.bb.bottom == 45 mm, "first dowel 45 mm up"
}
