# Request: a toy traffic light for a play-town, 6 mm ply with 3 mm coloured acrylic lenses.
# - Housing: a closed finger-jointed box 80 wide x 60 deep x 200 tall (outside), 12 mm
#   fingers.
# - Front: three 40 mm lens holes at 55 mm pitch, the middle one at the front's centre.
#   Above each hole, 4 mm clear of it, a 20 x 6 mortise for a visor.
# - Three visors: half discs R32 standing straight out of the front, each on one 20 mm
#   tenon through its mortise (the tenon's end flush with the front's inside face).
# - Three lens discs, 48 mm, in 3 mm red, amber and green acrylic, glued behind the holes.
# - A plinth 120 x 120, R10 corners, glued under the housing (centred), with "TOY TOWN"
#   engraved 8 mm tall in the middle of the strip in front of the housing.

import "std/joints.aidl"

thickness 6 mm

BOX_W = 80 mm
BOX_D = 60 mm
BOX_H = 200 mm
T = 6 mm
LENS_D = 40 mm
PITCH = 55 mm
VIS_R = 32 mm
GAP_ABOVE = 4 mm
DISC_D = 48 mm
COLOURS = ["green", "amber", "red"]

def lens_z(i) = BOX_H / 2 + (i - 1) * PITCH

def visor() -> solid {
    half = Sector(center=(0, 0), radius=VIS_R, start_angle=0 deg, end_angle=180 deg)
    tenon = tab_and_slot(part="tab", length=2 * VIS_R, thickness=T, tabs=1, tab=20 mm,
                         screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
}

def lens_disc(colour="red") -> solid {
    thickness 3 mm
    disc = Circle(center=(0, 0), diameter=DISC_D)
}

assembly traffic_light {
    box = finger_box(length=BOX_W, depth=BOX_D, height=BOX_H, thickness=T, finger=12 mm,
                     closed=true)

    hole front_cuts {
        for i in range(3) {
            lens = Circle(center=(0, (i - 1) * PITCH), diameter=LENS_D)
            mort = Rectangle(center=(0, (i - 1) * PITCH + LENS_D / 2 + GAP_ABOVE + T / 2),
                             width=20, height=T)
        }
    }
    Coincident(front_cuts.lens[1].center, box.front.outline.center)
    CutInto(front_cuts, box.front)

    for i in range(3) {
        vis = visor()
        disc = lens_disc(colour=COLOURS[i])
    }

    solid plinth {
        base = RoundedRectangle(center=(0, 0), width=120, height=120, corner_radius=10)
        drawing name {
            t = Text("TOY TOWN", position=(0, -(BOX_D / 2 + 60 mm) / 2), size=8,
                     valign="middle")
        }
    }

    # flat on the sheet: visors and discs in a column right of the net, the plinth below
    RightOf(vis[0], box, gap=8)
    AlignBottom(vis[0], box)
    Above(vis[1], vis[0], gap=6)
    AlignLeft(vis[1], vis[0])
    Above(vis[2], vis[1], gap=6)
    AlignLeft(vis[2], vis[0])
    RightOf(disc[0], vis[0], gap=8)
    AlignBottom(disc[0], box)
    Above(disc[1], disc[0], gap=6)
    AlignLeft(disc[1], disc[0])
    Above(disc[2], disc[1], gap=6)
    AlignLeft(disc[2], disc[0])
    Below(plinth, box, gap=8)
    AlignLeft(plinth, box)

    # assembled: the box stands on z = 0 centred on x = y = 0 (its front's outside at
    # y = -30); the visors lie flat, pointing forward, their tenon ends at y = -24
    for i in range(3) {
        Place(vis[i], position=(0, -BOX_D / 2 + T, lens_z(i) + LENS_D / 2 + GAP_ABOVE + T),
              face="down", up="front")
        Place(disc[i], position=(0, -BOX_D / 2 + T + 3 mm, lens_z(i)), face="front", up="up")
    }
    Place(plinth, position=(0, 0, -T))

    assert box.front.outline.bb.width == 80 mm and box.front.outline.bb.height == 200 mm,
        "front 80 x 200"
    assert len(front_cuts.lens) == 3, "three lenses"
    assert front_cuts.lens[0].diameter == 40 mm, "40 mm lens holes"
    assert front_cuts.lens[1].center.y - front_cuts.lens[0].center.y == 55 mm, "55 pitch"
    assert front_cuts.mort[0].bb.bottom - front_cuts.lens[0].bb.top == 4 mm, "mortise 4 above"
    assert front_cuts.mort[0].bb.width == 20 mm, "20 mm mortise"
    assert box.front.outline.bb.top - front_cuts.mort[2].bb.top >= T + 3 mm,
        "top mortise below the lid's joint"
    assert vis[0].half.radius == 32 mm, "visor R32"
    assert disc[0].disc.diameter == 48 mm, "48 mm discs"
    assert plinth.base.bb.width == 120 mm and plinth.base.bb.height == 120 mm, "plinth 120"
    assert len(vis) == 3 and len(disc) == 3, "three visors, three discs"
}
