# Request (home): a valet tray for the hall table, to empty my pockets into. 4 mm birch ply.
# Outside 240 mm long x 150 mm deep x 45 mm tall, open top, finger-jointed corners and base
# (12 mm fingers). A divider across the tray makes a key compartment 70 mm wide inside at the
# left end; it stands on two 20 mm tabs glued into slots in the base (0.1 mm clearance) and
# stops 0.3 mm short of the front and back walls. The front wall has a round-bottomed finger
# scoop, 36 mm wide and 25 mm deep, in the middle of the big compartment, and the monogram
# "J&M" engraved filled (serif bold, 16 mm tall) centred on the front of the key compartment.

import "std/joints.aidl"

thickness 4 mm

param length = 240 mm, min = 180 mm, max = 320 mm
param depth = 150 mm, min = 110 mm, max = 200 mm
param height = 45 mm, min = 30 mm, max = 70 mm
t = 4 mm
key_w = 70 mm        # inside width of the key compartment
end_gap = 0.3 mm     # divider short of the front and back walls each end

div_len = depth - 2 * t - 2 * end_gap
div_h = height       # from the tab tips (underside of the base) to the wall tops
div_x = -length / 2 + t + key_w + t / 2     # world x of the divider's middle

assembly valet_tray {
    box = finger_box(length=length, depth=depth, height=height, thickness=t, finger=12 mm,
                     closed=false)

    # the divider: drawn with its tab tips on y = 0, centred on x = 0
    solid divider {
        body = Rectangle(center=(0, div_h / 2), width=div_len, height=div_h)
        feet = tab_and_slot(part="tab", length=div_len, thickness=t, tabs=2, tab=20 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    RightOf(divider, box, gap=10)
    # standing across the tray, its top face towards +x, its tips on the underside of the base
    Place(divider, position=(div_x - t / 2, 0, 0), face="right", up="up")

    # the divider's slots in the base (the bottom lies centred on (0, 0), as in the world)
    base_slots = tab_and_slot(part="slot", length=div_len, thickness=t, tabs=2, tab=20 mm,
                              screw=0, clearance=0.1 mm, rotation=90 deg, cx=div_x, cy=0 mm)
    CutInto(base_slots, box.bottom)

    # finger scoop in the middle of the big compartment's front
    hole scoop {
        s = Slot(center=(0, 0), length=50 mm, width=36 mm, rotation=90 deg)
    }
    scoop.s.center.x == box.front.bb.left + t + key_w + t + (length - 3 * t - key_w) / 2
    scoop.s.center.y == box.front.bb.top
    CutInto(scoop, box.front)

    # the monogram on the front of the key compartment
    drawing mono {
        m = Text("J&M", position=(0, 0), size=16 mm, font="serif:Bold", valign="middle",
                 fill=true)
    }
    mono.m.position.x == box.front.bb.left + t + key_w / 2
    mono.m.position.y == (box.front.bb.top + box.front.bb.bottom) / 2
    CutInto(mono, box.front)

    # the request's numbers
    assert box.bottom.bb.width == 240 mm, "240 mm long outside"
    assert box.left.bb.height == 150 mm, "150 mm deep outside"
    assert box.front.bb.height == 45 mm, "45 mm tall"
    assert (div_x - t / 2) - (-length / 2 + t) == 70 mm, "key compartment 70 mm inside"
    assert divider.body.bb.width == 150 mm - 2 * 4 mm - 2 * 0.3 mm, "divider 0.3 mm short each end"
    assert scoop.s.bb.width == 36 mm, "scoop 36 mm wide"
    assert box.front.bb.top - scoop.s.bb.bottom == 25 mm, "scoop 25 mm deep"
    assert len(divider.feet.gap) == 3, "two tabs"
}
