# Request (music): a tray that clamps onto a microphone stand's 22 mm tube, for picks,
# a capo and a phone on stage. 6 mm ply, glued.
# - Tray base 160 x 110 mm with R10 corners; at the back a tongue reaching a 56 mm
#   round end whose 22.5 mm bore is 80 mm behind the tray's centre; "ON STAGE" engraved
#   in the middle, bold, filled, 10 mm high.
# - A rim glued on the base: the same 160 x 110 R10 outline, 10 mm wide.
# - A collar under the tongue from three 56 mm rings with the 22.5 mm bore; the middle
#   ring holds an M3 thumbscrew and its nut in a T-slot entering from the front edge,
#   (FIX after the first valid program: from the back edge, away from the tray)
#   reaching the bore, so the screw tip presses on the tube.

import "std/fasteners.aidl"

thickness 6 mm

param t = 6 mm
tray_w = 160 mm
tray_d = 110 mm
rim_w = 10 mm
collar_d = 56 mm
bore_d = 22.5 mm
pole_y = 80 mm          # bore centre behind the tray's centre

def ring(screw=false) -> solid {
    disc = Circle(center=(0, 0), diameter=collar_d)
    hole bore {
        c = Circle(center=(0, 0), diameter=bore_d)
    }
    if screw {
        # FIX after the first valid program: from the ring's BACK edge to the bore; from the
        # front edge the thumbscrew's head sat under the tray, out of the fingers' reach
        clamp = t_slot(size=3, length=collar_d / 2 - bore_d / 2 + 0.5 mm, nut_depth=6 mm,
                       rotation=0 deg, cx=0, cy=collar_d / 2)
    }
    Fixed(disc)
}

assembly mic_stand_tray {
    solid base {
        tray = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_d, corner_radius=10)
        tongue = Hull(Rectangle(center=(0, tray_d / 2 - 5 mm), width=80, height=10),
                      Circle(center=(0, pole_y), diameter=collar_d))
        hole bore {
            c = Circle(center=(0, pole_y), diameter=bore_d)
        }
        drawing label {
            word = Text("ON STAGE", position=(0, 0), size=10, font="sans:Bold",
                        valign="middle", fill=true)
        }
        Fixed(tray)
    }

    solid rim {
        outer = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_d, corner_radius=10)
        hole opening {
            r = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_d, corner_radius=10)
            w = Inset(r, rim_w)
            Fixed(r)
        }
        Fixed(outer)
    }

    top_ring = ring()
    mid_ring = ring(screw=true)
    low_ring = ring()

    # on the sheet
    RightOf(rim, base, gap=8)
    AlignBottom(rim, base)
    Below(top_ring, base, gap=8)
    AlignLeft(top_ring, base)
    RightOf(mid_ring, top_ring, gap=8)
    AlignTop(mid_ring, top_ring)
    RightOf(low_ring, mid_ring, gap=8)
    AlignTop(low_ring, mid_ring)

    # in 3D: the base on z = 0, the rim on it, the collar under the tongue
    Place(base, position=(0, 0, 0), face="up")
    Place(rim, position=(0, 0, t), face="up")
    Place(top_ring, position=(0, pole_y, -t), face="up")
    Place(mid_ring, position=(0, pole_y, -2 * t), face="up")
    Place(low_ring, position=(0, pole_y, -3 * t), face="up")

    # the request's numbers
    assert base.tray.width == 160 mm and base.tray.height == 110 mm, "160 x 110 tray"
    assert base.bore.c.center.y - base.tray.center.y == 80 mm, "bore 80 behind the centre"
    assert base.bore.c.diameter == 22.5 mm and mid_ring.bore.c.diameter == 22.5 mm, "bore"
    assert rim.outer.bb.width - rim.opening.w.bb.width == 2 * 10 mm, "rim 10 mm wide"
    assert mid_ring.clamp.slot.bb.bottom <= mid_ring.bore.c.top.y, "screw reaches the bore"
}
