# Request: a cuttlebone holder for a budgie cage, in 3 mm clear acrylic (bird-safe, wipes
# clean). The bone (up to 130 x 50 x 15 mm) stands upright against the cage bars (2 mm wire).
# Inside the cage a front frame, a stadium 80 x 176 mm, with an elliptical pecking window
# 44 x 112 mm in its middle; outside the cage a back plate of the same stadium with the bird's
# name "KIWI" in bold sans 16 mm, filled engraving, reading upwards. Two M4 bolts with wing
# nuts clamp the two plates through the bars: one 77 mm above the centre, one 79 mm below.
# A ledge 44 mm wide standing 14 mm out from the frame's back holds the bone up; it is glued
# into the frame by two 10 mm tabs in mortises whose top edge is 65 mm below the centre.

import "std/fasteners.aidl"
import "std/joints.aidl"

t = 3 mm
thickness t

plate_w = 80 mm
plate_l = 176 mm
bolt_up = 77 mm
bolt_down = 79 mm
ledge_w = 44 mm
ledge_d = 14 mm
ledge_top = -65 mm         # the mortises' top edge, from the frame's centre
bone = 15 mm
z0 = 100 mm                # height of the plates' centres in the model

assembly holder {
    solid frame {
        body = Slot(center=(0, 0), length=plate_l, width=plate_w, rotation=90)
        hole window { e = Ellipse(center=(0, 0), rx=22, ry=56) }
        top = clearance_hole(size=4)
        bottom = clearance_hole(size=4)
        At(top.c.center, body.center, dy=bolt_up)
        At(bottom.c.center, body.center, dy=-bolt_down)
        mortise = tab_and_slot(part="slot", length=ledge_w, thickness=t, tabs=2, tab=10 mm,
                               screw=0, cx=0 mm, cy=ledge_top - t / 2)
    }

    solid back {
        body = Slot(center=(0, 0), length=plate_l, width=plate_w, rotation=90)
        top = clearance_hole(size=4)
        bottom = clearance_hole(size=4)
        At(top.c.center, body.center, dy=bolt_up)
        At(bottom.c.center, body.center, dy=-bolt_down)
        drawing name {
            n = Text("KIWI", position=(0, 0), size=16, font="sans:Bold", valign="middle",
                     rotation=90, fill=true)
        }
    }

    # the ledge: its tabs' tips on y = 0, the body below; t of it sits in the frame
    solid ledge {
        body = Rectangle(center=(0, -(ledge_d + t) / 2), width=ledge_w, height=ledge_d + t)
        tenon = tab_and_slot(part="tab", length=ledge_w, thickness=t, tabs=2, tab=10 mm,
                             screw=0, cx=0 mm, cy=0 mm)
    }

    # on the sheet
    RightOf(back, frame, gap=8)
    AlignTop(back, frame)
    RightOf(ledge, back, gap=8)
    AlignTop(ledge, back)

    # in 3D: the bars on y = 0 (from -1 to 1 mm); the bird's side is -y (front)
    Place(back, position=(0, 1 mm, z0), face="back", up="up")
    Place(frame, position=(0, -1 mm - bone, z0), face="front", up="up")
    # FIX after the first valid program: up="back" turned the ledge out into the bird's side
    # of the frame, its tabs not in their mortises (no message); its tabs' tips are on the
    # frame's front face and its body runs back towards the bars: up="front"
    Place(ledge, position=(0, -1 mm - bone - t, z0 + ledge_top - t), face="up", up="front")

    # the request's numbers
    assert frame.body.width == 80 mm and frame.body.length == 176 mm
    assert frame.window.e.rx * 2 == 44 mm and frame.window.e.ry * 2 == 112 mm
    assert frame.top.c.center.y - frame.body.center.y == 77 mm
    assert frame.body.center.y - frame.bottom.c.center.y == 79 mm
    assert back.top.c.center.y - back.bottom.c.center.y == 156 mm
    assert frame.top.c.diameter >= 4.3 mm, "M4 clearance"
    assert ledge.body.width == 44 mm and ledge.body.height - t == 14 mm
    assert frame.mortise.slot[0].bb.top - frame.body.center.y == -65 mm
    assert len(frame.mortise.slot) == 2 and len(ledge.tenon.gap) == 3
    assert frame.top.c.bb.bottom - frame.mortise.slot[0].bb.top >= 130 mm, "room for a 130 mm bone"
    assert back.name.n.size == 16 mm
    assert distance(back.name, back.top) >= 5 mm and distance(back.name, back.bottom) >= 5 mm
}
