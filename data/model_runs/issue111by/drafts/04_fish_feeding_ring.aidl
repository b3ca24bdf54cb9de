# Request: "A feeding ring for my aquarium that keeps the flakes in one spot, 3 mm clear
# acrylic, held to the glass by a suction cup. The ring is 80 mm outside and 60 mm inside,
# with an ear 24 mm wide reaching 20 mm beyond the ring on the glass side (its two end
# corners r4, r3 where it meets the ring). A bracket 24 mm wide stands up 60 mm from the ear,
# its 12 mm tenon in a mortise (0.1 mm play) whose back face is 8 mm in from the ear's tip
# (room for the suction cup behind it). The bracket has a keyhole for the cup's knob: 7 mm
# head centred 15 mm below its top, 3.5 mm slot 8 mm long, upward. The fish's name NEMO
# engraved 4 mm tall on the ring, opposite the ear, reading the right way up."

import "std/joints.aidl"
import "std/plates.aidl"

units mm
thickness 3 mm

sheet_t = 3 mm
ring_od = 80 mm
ring_id = 60 mm
ear_w = 24 mm
ear_reach = 20 mm
cup_room = 8 mm
bracket_h = 60 mm
tenon = 12 mm
mortise_y = ring_od / 2 + ear_reach - cup_room - sheet_t / 2

assembly feeder {
    solid r {
        disc = Circle(center=(0, 0), diameter=ring_od)
        ear = RoundedRectangle(center=(0, ring_od / 2 - 5 + (ear_reach + 5) / 2), width=ear_w,
                               height=ear_reach + 5, corner_radii=[4, 4, 0, 0])
        hole opening { c = Circle(center=(0, 0), diameter=ring_id) }
        mortise = tab_and_slot(part="slot", length=ear_w, thickness=sheet_t, tabs=1, tab=tenon,
                               screw=0, clearance=0.1 mm, cx=0, cy=mortise_y)
        drawing name {
            path = Circle(center=(0, 0), radius=(ring_od + ring_id) / 4, construction=true)
            t = Text("NEMO", along=path, size=4, valign="middle", flip=true)
        }
        Concentric(name.path, disc)
        Fillet([ear, disc], 3)
    }

    solid b {
        body = Rectangle(bottom_left=(-ear_w / 2, -sheet_t), width=ear_w, height=bracket_h + sheet_t)
        # the tenon on the bottom edge (the panel above it: 180 deg), tips at y = -3
        tenon_cut = tab_and_slot(part="tab", length=ear_w, thickness=sheet_t, tabs=1, tab=tenon,
                                 screw=0, rotation=180 deg, cx=0, cy=-sheet_t)
        kh = keyhole(head=7 mm, slot_width=3.5 mm, length=8 mm, direction=90 deg, cx=0,
                     cy=bracket_h - 15 mm)
    }

    RightOf(b, r, gap=8)
    AlignBottom(b, r)
    # assembled: the bracket stands on the ear, shoulders on the ring's top face
    Place(r, position=(0, 0, 0))
    Place(b, position=(0, mortise_y + sheet_t / 2, sheet_t), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert abs(r.disc.diameter - 80 mm) < 0.01 and abs(r.opening.c.diameter - 60 mm) < 0.01,
        "ring 80 / 60"
    assert abs(r.ear.bb.width - 24 mm) < 0.01, "ear 24 wide"
    assert abs((r.ear.bb.top - r.disc.bb.top) - 20 mm) < 0.01, "ear 20 beyond the ring"
    assert abs((r.ear.bb.top - r.mortise.slot[0].bb.center_y) - (8 mm + 1.5 mm)) < 0.01,
        "bracket's back face 8 mm in from the tip"
    assert abs(r.mortise.slot[0].bb.width - 12.1 mm) < 0.01, "mortise 12 + 0.1"
    assert abs(b.body.bb.width - 24 mm) < 0.01, "bracket 24 wide"
    assert abs((b.body.bb.top - b.tenon_cut.bb.top) - 60 mm) < 0.01, "60 mm above the ring"
    assert abs((b.body.bb.top - b.kh.head_hole.center.y) - 15 mm) < 0.01, "keyhole 15 below top"
    assert abs(b.kh.head_hole.diameter - 7 mm) < 0.01, "7 mm head"
    # the name stays on the band, opposite the ear
    assert r.name.t.bb.top < r.opening.c.bb.bottom + 0 mm or r.name.t.bb.center_y < 0,
        "name opposite the ear"
    assert r.name.t.bb.bottom > r.disc.bb.bottom, "name on the band"
}
