# Request: a wall candle sconce for a glass votive (75 mm across), cut from 6 mm ply.
# Back plate 120 mm wide and 300 mm tall with a round arched top (R60), hung on a keyhole
# (9 mm head) 32 mm below the top, a five-point star (44 mm across) cut out behind the
# flame, and "HYGGE" engraved filled above the star. A shelf 120 mm wide that projects
# 110 mm from the wall, its front corners R20, its bottom 100 mm above the plate's bottom,
# glued into the plate by two 30 mm tabs. Under it a curved bracket (back edge 90 mm,
# top edge 79 mm) tabbed into both. A ring (96 mm outside, 78 mm bore) glued on the shelf
# keeps the votive from sliding off.

units mm
thickness 6 mm
import "std/joints.aidl"
import "std/plates.aidl"

T = 6 mm
shelf_z = 100 mm        # the shelf's bottom face above the plate's bottom edge
bracket_top = 79 mm     # bracket's top edge under the shelf (from the plate's front face)
bracket_back = 90 mm    # bracket's back edge on the plate (from the shelf's bottom)

assembly sconce {
    solid back {
        body = Rectangle(bottom_left=(-60, 0), width=120, height=240)
        arch = Circle(center=(0, 240), radius=60)
        kh = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=0 mm, cy=268 mm)
        hole star {
            s = Star(center=(0, 205), points=5, outer_radius=22, inner_radius=9)
        }
        drawing label {
            t = Text("HYGGE", position=(0, 236), size=10, font="sans:Bold", fill=true)
        }
        # mortises for the shelf's two tabs (the shelf's middle at shelf_z + T / 2)
        shelf_mortise = tab_and_slot(part="slot", length=120 mm, thickness=T, tabs=2, tab=30 mm,
                                     screw=0, cx=0 mm, cy=shelf_z + T / 2)
        # mortises for the bracket's back tabs (bracket stands at x = 0, under the shelf)
        bracket_mortise = tab_and_slot(part="slot", length=bracket_back, thickness=T, tabs=2,
                                       tab=20 mm, screw=0, rotation=90 deg, cx=0 mm,
                                       cy=shelf_z - bracket_back / 2)
    }

    solid shelf {
        # frame: y = 0 is the tab tips (flush with the plate's back face), the front at -116
        body = RoundedRectangle(bottom_left=(-60, -(110 + T)), width=120, height=110 + T,
                                corner_radii=[0, 0, 20, 20])
        tabs = tab_and_slot(part="tab", length=120 mm, thickness=T, tabs=2, tab=30 mm,
                            screw=0, cx=0 mm, cy=0 mm)
        bracket_mortise = tab_and_slot(part="slot", length=bracket_top, thickness=T, tabs=2,
                                       tab=20 mm, screw=0, rotation=90 deg, cx=0 mm,
                                       cy=-(T + bracket_top / 2))
    }

    solid bracket {
        # frame: x from the plate's back face toward the room, y = 0 the shelf's top face
        top = Line((T, 0), (T + bracket_top, 0))
        nose = Line((T + bracket_top, 0), (T + bracket_top, -8))
        curve = Arc(start=(T + bracket_top, -8), through=(37.2, -41.6), end=(8, -(T + bracket_back)))
        foot = Line((8, -(T + bracket_back)), (0, -(T + bracket_back)))
        back_edge = Line((0, -(T + bracket_back)), (0, -T))
        notch_a = Line((0, -T), (T, -T))
        notch_b = Line((T, -T), (T, 0))
        back_tabs = tab_and_slot(part="tab", length=bracket_back, thickness=T, tabs=2,
                                 tab=20 mm, screw=0, rotation=90 deg, cx=0 mm,
                                 cy=-(T + bracket_back / 2))
        top_tabs = tab_and_slot(part="tab", length=bracket_top, thickness=T, tabs=2,
                                tab=20 mm, screw=0, cx=T + bracket_top / 2, cy=0 mm)
        Rigid(self)
    }

    solid ring {
        outer = Circle(center=(0, 0), diameter=96)
        hole bore { c = Circle(center=(0, 0), diameter=78) }
    }

    # flat layout for the sheet
    RightOf(shelf, back, gap=10)
    AlignTop(shelf, back)
    RightOf(bracket, shelf, gap=10)
    AlignTop(bracket, back)
    Below(ring, shelf, gap=10)
    AlignLeft(ring, shelf)

    # 3D: plate against the wall (its back face at y = 0), shelf and bracket into it
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(shelf, position=(0, 0, shelf_z), face="up")
    Place(bracket, position=(T / 2, 0, shelf_z + T), face="left", up="up")
    Place(ring, position=(0, -(T + 55), shelf_z + T), face="up")

    # the request's numbers
    assert back.bb.width == 120 mm, "plate 120 wide"
    assert back.bb.height == 300 mm, "plate 300 tall"
    assert back.bb.top - back.kh.head_hole.center.y == 32 mm, "keyhole 32 below the top"
    assert shelf.body.bb.height - T == 110 mm, "shelf projects 110 from the wall"
    assert ring.outer.diameter == 96 mm and ring.bore.c.diameter == 78 mm, "ring 96 / 78"
    assert ring.bore.c.diameter - 75 mm >= 2 mm, "votive (75) drops into the ring"
    assert ring.outer.diameter / 2 + 55 mm <= 110 mm, "ring stays on the shelf"
}
