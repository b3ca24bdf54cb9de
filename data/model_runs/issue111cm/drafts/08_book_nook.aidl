# Request: a book nook as a birthday gift: an insert that stands on a bookshelf between the
# books and shows a lamp-lit alley in depth. From 3 mm plywood. A finger-jointed box open at
# the front, 100 mm wide, 200 mm tall and 150 mm deep outside (back, floor, ceiling, two
# sides). Inside, three scenery layers stand parallel to the back, 35, 75 and 115 mm in front
# of the back's inner face, each 0.5 mm clear of the sides and held by one 30 mm tenon at the
# top and one at the bottom in mortises through the ceiling and floor (0.2 mm clearance).
# Front layer: the alley's two house walls with lit windows (6 x 8 mm) and a 12 mm kerb rail
# along the bottom engraved "FOR ANNA - 2026" (4 mm); middle layer: a bookshop whose wall
# carries "BOOKS & TEA" engraved filled, bold sans 5 mm, reading upwards; back layer:
# distant rooftops with a chimney and small 3 x 4 mm lit windows. The back has a 20 mm
# round moon window, 18 mm right of and 55 mm above its centre. A 5 mm hole in the ceiling,
# 15 mm in front of the back, for the fairy-light wire.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
nook_w = 100 mm
nook_h = 200 mm
nook_d = 150 mm
layer_w = nook_w - 2 * t - 2 * 0.5 mm
layer_h = nook_h               # inner height + a tenon through the floor and the ceiling
depths = [35 mm, 75 mm, 115 mm]
fit = 0.2 mm

def tenons() -> hole {
    top = tab_and_slot(part="tab", length=layer_w, thickness=t, tabs=1, tab=30 mm, screw=0,
                       cx=0 mm, cy=layer_h / 2)
    bottom = tab_and_slot(part="tab", length=layer_w, thickness=t, tabs=1, tab=30 mm,
                          screw=0, rotation=180 deg, cx=0 mm, cy=-layer_h / 2)
}

def mortises() -> hole {
    ref = Point(0, 0, construction=true)
    for d in depths {
        m = tab_and_slot(part="slot", length=layer_w, thickness=t, tabs=1, tab=30 mm,
                         screw=0, clearance=fit, cx=0 mm, cy=d)
    }
    Rigid(self)
}

assembly book_nook {
    # finger_box's bottom is the nook's back, its front and back the floor and ceiling,
    # its open top the nook's opening
    box = finger_box(length=nook_w, depth=nook_h, height=nook_d, thickness=t, finger=10 mm,
                     closed=false)

    floor_slots = mortises()
    floor_slots.ref.x == box.front.bb.center_x
    floor_slots.ref.y == box.front.bb.bottom + t
    CutInto(floor_slots, box.front)

    ceiling_slots = mortises()
    ceiling_slots.ref.x == box.back.bb.center_x
    ceiling_slots.ref.y == box.back.bb.bottom + t
    CutInto(ceiling_slots, box.back)

    hole wire { c = Circle(center=(0, 0), diameter=5 mm) }
    wire.c.center.x == box.back.bb.center_x
    wire.c.center.y == box.back.bb.bottom + t + 15 mm
    CutInto(wire, box.back)

    hole moon { c = Circle(center=(0, 0), diameter=20 mm) }
    At(moon.c.center, box.bottom.bb.center, dx=18 mm, dy=55 mm)
    CutInto(moon, box.bottom)

    solid front_layer {
        panel = Rectangle(center=(0, 0), width=layer_w, height=layer_h)
        joints = tenons()
        hole alley {
            gap = Polygon([(-20, -85), (25, -85), (25, 30), (33, 30), (33, 72), (40, 72),
                           (40, 85), (-40, 85), (-40, 62), (-20, 50)])
        }
        for y in [-60, -35, -10, 15] {
            hole lit_l { w = Rectangle(center=(-33, y), width=6, height=8) }
            hole lit_r { w = Rectangle(center=(36, y), width=6, height=8) }
        }
        drawing dedication {
            words = Text("FOR ANNA - 2026", position=(0, -91), size=4, valign="middle")
        }
    }

    solid middle_layer {
        panel = Rectangle(center=(0, 0), width=layer_w, height=layer_h)
        joints = tenons()
        hole street {
            gap = Polygon([(-12, -85), (14, -85), (14, 45), (20, 45), (20, 85), (-26, 85),
                           (-26, 58), (-12, 58)])
        }
        for y in [-50, -20, 10, 40] {
            hole lit_r { w = Rectangle(center=(31, y), width=6, height=8) }
        }
        drawing shop_sign {
            words = Text("BOOKS & TEA", position=(-29, -20), size=5, font="sans:Bold",
                         valign="middle", rotation=90 deg, fill=true)
        }
    }

    solid back_layer {
        panel = Rectangle(center=(0, 0), width=layer_w, height=layer_h)
        joints = tenons()
        hole sky {
            gap = Polygon([(-40, 85), (40, 85), (40, 5), (32, 5), (32, 15), (28, 15), (28, 5),
                           (20, 5), (20, -12), (5, -12), (5, 10), (-5, 10), (-10, 18),
                           (-15, 10), (-15, -5), (-30, -5), (-30, -20), (-40, -20)])
        }
        for p in [(-35, -35), (-22, -20), (-8, -5), (12, -27), (34, -10)] {
            hole lit { w = Rectangle(center=p, width=3, height=4) }
        }
    }

    RightOf(front_layer, box, gap=10)
    RightOf(middle_layer, front_layer, gap=10)
    RightOf(back_layer, middle_layer, gap=10)
    AlignCenterY(front_layer, box)
    AlignCenterY(middle_layer, box)
    AlignCenterY(back_layer, box)
    # assembled as finger_box stands (the nook lying on its back): each layer flat, at its
    # depth above the back's inner face
    Place(back_layer, position=(0, 0, t + depths[0] - t / 2), face="up")
    Place(middle_layer, position=(0, 0, t + depths[1] - t / 2), face="up")
    Place(front_layer, position=(0, 0, t + depths[2] - t / 2), face="up")

    assert box.length == 100 mm and box.depth == 200 mm and box.height == 150 mm,
        "100 wide, 200 tall, 150 deep"
    assert nook_w - 2 * t - front_layer.panel.width == 2 * 0.5 mm, "0.5 mm clear each side"
    assert depths == [35 mm, 75 mm, 115 mm], "layers 35, 75 and 115 mm in front of the back"
    assert len(floor_slots.m) == 3 and len(ceiling_slots.m) == 3, "three mortises each"
    assert moon.c.center.x - box.bottom.bb.center_x == 18 mm and
        moon.c.center.y - box.bottom.bb.center_y == 55 mm, "moon 18 right, 55 up"
}
