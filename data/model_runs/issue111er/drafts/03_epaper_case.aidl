# Request: a desk frame for a 7.5-inch e-paper panel (outline 170.2 x 111.2 mm) driven
# by a Raspberry Pi Zero on its back, in 3 mm birch ply.
# - Three layers 200 x 140 with 6 mm corner radii, screwed together by 4 M3 screws
#   8 mm in from the edges (medium clearance holes through all three).
# - Front bezel: a 164 x 99 window, its centre 2 mm above the middle.
# - Spacer: a 171 x 112 pocket for the panel and a 36 mm wide notch under it, 6 deep,
#   for the flat cable.
# - Back: a 36 x 4 slot for the flat cable, centred 10 mm above the bottom edge; the Pi
#   Zero's four M2.5 holes (medium clearance), a 58 x 23 pattern centred 25 mm below the
#   middle; "KITCHEN WEATHER" engraved 8 mm high in bold on its outer (rear) face,
#   45 mm above the middle.
# - Two feet, 90 long x 40 tall, 70 mm either side of the middle, hold the 9 mm stack
#   leaning back 15 degrees in a 9.3 mm wide slot whose floor is 16 mm above the table.

units mm
t = 3 mm
thickness t
kerf 0.15 mm

import "std/fasteners.aidl"

plate_w = 200 mm
plate_h = 140 mm
lean = 15 deg
stack = 3 * t

# 3D helpers: the stack leans back by `lean`; u: the plates' up, n: their front normal
ux = sin(lean)        # y part of u
uz = cos(lean)        # z part of u
nx = -cos(lean)       # y part of n
nz = sin(lean)        # z part of n
slot_x = 40 mm        # slot floor's middle in the foot drawing (world y)
slot_y = 16 mm        # slot floor above the table
# the rear face's bottom edge, middle (world y, z)
rear_y = slot_x - stack / 2 * nx
rear_z = slot_y - stack / 2 * nz

def layer() -> solid {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=6 mm)
    s1 = clearance_hole(size=3, cx=-(plate_w / 2 - 8 mm), cy=-(plate_h / 2 - 8 mm))
    s2 = clearance_hole(size=3, cx=plate_w / 2 - 8 mm, cy=-(plate_h / 2 - 8 mm))
    s3 = clearance_hole(size=3, cx=plate_w / 2 - 8 mm, cy=plate_h / 2 - 8 mm)
    s4 = clearance_hole(size=3, cx=-(plate_w / 2 - 8 mm), cy=plate_h / 2 - 8 mm)
    Fixed(body)
    Fixed(s1)
    Fixed(s2)
    Fixed(s3)
    Fixed(s4)
}

def foot() -> solid {
    outline = Polygon([(0, 0), (90, 0), (90, 10), (60, 40), (25, 40), (0, 10)])
    hole seat {
        # the slot, along the plates' up direction (leaning back toward +x)
        bar = Rectangle(start=(slot_x, slot_y),
                        end=(slot_x + 40 mm * ux, slot_y + 40 mm * uz), width=stack + 0.3 mm)
    }
    Fixed(outline)
    Fixed(seat)
}

assembly epaper_frame {
    solid bezel {
        plate = layer()
        hole window { r = Rectangle(center=(0, 2 mm), width=164 mm, height=99 mm) }
        Fixed(window)
    }
    solid spacer {
        plate = layer()
        hole pocket {
            r = Rectangle(center=(0, 0), width=171 mm, height=112 mm)
            notch = Rectangle(center=(0, -56 mm - 3 mm), width=36 mm, height=6 mm)
        }
        Fixed(pocket)
    }
    solid back {
        plate = layer()
        hole cable { r = Rectangle(center=(0, -plate_h / 2 + 10 mm), width=36 mm, height=4 mm) }
        Fixed(cable)
        pi1 = clearance_hole(size=2.5, cx=-29 mm, cy=-25 mm - 11.5 mm)
        pi2 = clearance_hole(size=2.5, cx=29 mm, cy=-25 mm - 11.5 mm)
        pi3 = clearance_hole(size=2.5, cx=29 mm, cy=-25 mm + 11.5 mm)
        pi4 = clearance_hole(size=2.5, cx=-29 mm, cy=-25 mm + 11.5 mm)
        Fixed(pi1)
        Fixed(pi2)
        Fixed(pi3)
        Fixed(pi4)
        drawing name {
            words = Text("KITCHEN WEATHER", position=(0, 45 mm), size=8 mm, font="sans:Bold",
                         valign="middle", fill=true)
        }
        Fixed(name)
    }
    foot_l = foot()
    foot_r = foot()

    # flat layout
    RightOf(spacer, bezel, gap=5)
    AlignBottom(spacer, bezel)
    RightOf(back, spacer, gap=5)
    AlignBottom(back, spacer)
    Below(foot_l, bezel, gap=5)
    AlignLeft(foot_l, bezel)
    RightOf(foot_r, foot_l, gap=5)
    AlignBottom(foot_r, foot_l)

    # 3D: x across, y to the back, z up; every plate's centre is 70 up its face from
    # the bottom edge. The back is turned so its engraving faces the rear.
    Place(back, position=(0, rear_y + t * nx + plate_h / 2 * ux, rear_z + t * nz + plate_h / 2 * uz),
          rotation=(90 deg + lean, 0, 180 deg))
    Place(spacer, position=(0, rear_y + t * nx + plate_h / 2 * ux, rear_z + t * nz + plate_h / 2 * uz),
          rotation=(90 deg - lean, 0, 0))
    Place(bezel, position=(0, rear_y + 2 * t * nx + plate_h / 2 * ux, rear_z + 2 * t * nz + plate_h / 2 * uz),
          rotation=(90 deg - lean, 0, 0))
    Place(foot_l, position=(-70 mm - t / 2, 0, 0), face="right", up="up")
    Place(foot_r, position=(70 mm - t / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert bezel.plate.body.width == 200 mm and bezel.plate.body.height == 140 mm
    assert bezel.window.r.width == 164 mm and bezel.window.r.height == 99 mm
    assert bezel.window.r.center.y - bezel.plate.body.center.y == 2 mm
    assert spacer.pocket.r.width == 171 mm and spacer.pocket.r.height == 112 mm
    assert spacer.pocket.r.width >= 170.2 mm and spacer.pocket.r.height >= 111.2 mm, "panel fits"
    assert spacer.pocket.notch.width == 36 mm and spacer.pocket.notch.height == 6 mm
    assert spacer.pocket.r.bb.bottom - spacer.pocket.notch.bb.bottom == 6 mm, "notch 6 deep under the pocket"
    assert back.cable.r.center.y - back.plate.body.bb.bottom == 10 mm
    assert back.pi2.c.center.x - back.pi1.c.center.x == 58 mm and back.pi3.c.center.y - back.pi2.c.center.y == 23 mm
    assert back.plate.body.center.y - (back.pi1.c.center.y + back.pi4.c.center.y) / 2 == 25 mm
    assert back.plate.body.bb.right - back.plate.s3.c.center.x == 8 mm and back.plate.body.bb.top - back.plate.s3.c.center.y == 8 mm
    # the cable slot lies under the spacer's notch, which lies under the panel's pocket
    assert back.cable.r.bb.bottom - back.plate.body.bb.bottom >= spacer.pocket.notch.bb.bottom - spacer.plate.body.bb.bottom
    assert back.cable.r.bb.top - back.plate.body.bb.bottom <= spacer.pocket.r.bb.bottom - spacer.plate.body.bb.bottom
    # the window shows within the pocket; the screws clear the pocket
    assert distance(spacer.pocket, spacer.plate.s3) >= 3 mm
    assert distance(back.name, back.pi3) >= 10 mm and distance(back.name, back.plate.s4) >= 3 mm
    assert foot_l.outline.bb.width == 90 mm and foot_l.outline.bb.height == 40 mm
    assert foot_l.seat.bar.width == 9.3 mm and stack == 9 mm
    assert lean == 15 deg
}
