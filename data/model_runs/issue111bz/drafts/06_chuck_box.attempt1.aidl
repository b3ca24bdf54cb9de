# Request (camping): a camp kitchen ("chuck") box to carry the stove, pans and plates in the car,
# 6 mm birch ply, finger-jointed all round with 30 mm fingers, 450 x 300 x 320 mm outside.
# - A carrying handle slot in each end (left and right): 120 x 30 mm, rounded, 40 mm below the
#   top edge, centred front to back.
# - Vents for the stove in the back: 3 rows of 8 holes 8 mm, on a 25 mm grid, the grid's centre
#   60 mm above the back's centre.
# - On the lid, engraved filled: "CAMP KITCHEN" (bold, at most 360 mm long) with a row of three
#   pine trees (two stacked triangles and a trunk each, 60 mm tall) centred above it.
import "std/joints.aidl"

thickness 6 mm

def pine(x=0 mm, y=0 mm) -> drawing {
    lower = Triangle(center=(x, y + 20), base=44, height=30, fill=true)
    upper = Triangle(center=(x, y + 40), base=32, height=24, fill=true)
    trunk = Rectangle(center=(x, y + 2.5), width=8, height=5, fill=true)
}

assembly chuck_box {
    box = finger_box(length=450 mm, depth=300 mm, height=320 mm, thickness=6 mm, finger=30 mm,
                     closed=true)

    hole handle_l { s = Slot(center=(0, 0), length=120, width=30, rotation=90 deg) }
    hole handle_r { s = Slot(center=(0, 0), length=120, width=30, rotation=90 deg) }
    # the sides lie on their side, top edge outward: the left's at -x, the right's at +x
    handle_l.bb.left == box.left.bb.left + 40 mm
    handle_r.bb.right == box.right.bb.right - 40 mm
    AlignCenterY(handle_l, box.left)
    AlignCenterY(handle_r, box.right)
    CutInto(handle_l, box.left)
    CutInto(handle_r, box.right)

    hole vents {
        c = Circle(center=(0, 0), diameter=8)
        grid = GridPattern(c, 3, 8, (25, 25))
    }
    AlignCenterX(vents, box.back)
    vents.bb.center_y == box.back.bb.center_y + 60 mm
    CutInto(vents, box.back)

    drawing lid_art {
        word = Text("CAMP KITCHEN", position=(0, 0), size=40, font="sans:Bold", valign="middle",
                    fill=true, max_width=360 mm)
        trees = [pine(x=dx, y=40 mm) for dx in [-60 mm, 0 mm, 60 mm]]
    }
    CenterInside(lid_art, box.lid)
    CutInto(lid_art, box.lid)

    assert box.front.bb.width == 450 mm, "450 long"
    assert box.left.bb.height == 300 mm, "300 deep"
    assert box.front.bb.height == 320 mm, "320 tall"
    assert handle_l.bb.left - box.left.bb.left == 40 mm, "handle 40 mm below the top"
    assert handle_l.s.length == 120 mm and handle_l.s.width == 30 mm, "handle 120 x 30"
    assert len(vents.grid) == 24, "24 vent holes"
    assert vents.bb.top <= box.back.bb.top - 20 mm, "vents clear of the top fingers"
    assert lid_art.word.bb.width <= 360 mm, "name at most 360 mm"
    assert lid_art.bb.height <= box.lid.bb.height - 40 mm, "art on the lid"
}
