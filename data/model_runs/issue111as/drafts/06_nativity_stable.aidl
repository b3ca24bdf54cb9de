# Request (holidays): a Christmas nativity stable, flat-packed from 3 mm ply, glued.
#  - base 220 x 130 mm (5 mm rounded corners), "NOEL" engraved as filled bold letters 12 mm tall
#    in the middle of the 25 mm strip in front of the stable;
#  - back wall 200 mm wide, 110 mm tall at the eaves, a gable to 160 mm at the middle, a
#    5-point star window (12 / 5 mm radii) centred 125 mm up; on the apex a 6 mm post carrying a
#    5-point star (16 / 7 mm radii) centred 188 mm up; three 20 mm tabs into the base;
#  - two side walls 90 mm deep x 110 mm tall, standing flush with the back wall's ends and
#    glued to its front face, each with an arched window (20 mm wide, 25 mm to the spring of
#    a 10 mm radius arch, centred 45 mm from the back and 60 mm up) and two 20 mm tabs into the
#    base;
#  - two roof panels 118 x 100 mm lying on the gable's slopes, from the ridge to 5 mm past the
#    eaves, their back edge against the back wall's front face, with seven engraved shingle
#    lines 15 mm apart parallel to the ridge.
# Assembled in 3D.

import "std/joints.aidl"

thickness 3 mm

mat = 3 mm
wall_w = 200 mm
eave = 110 mm
apex = 160 mm
depth = 90 mm
roof_angle = atan((apex - eave) / (wall_w / 2))
front_y = -50 mm              # world y of the side walls' front edges
back_y = 40 mm                # world y of the back wall's front face
base_y = -10 mm               # world y of the base's centre

def side_wall() -> solid {
    # own frame: x from the back (0) toward the front, y = 0 the base's top, tabs to y = -mat
    body = Rectangle(bottom_left=(0, -mat), width=depth, height=eave + mat)
    t = tab_and_slot(part="tab", length=depth, thickness=mat, tabs=2, tab=20 mm, screw=0,
                     rotation=180 deg, cx=depth / 2, cy=-mat)
    hole window {
        sill = Rectangle(center=(45, 60), width=20, height=25)
        arch = Circle(center=(45, 72.5), radius=10)
    }
}

def roof() -> solid {
    # own frame: x from the ridge (0) down the slope, y across the depth, z up from the gable
    panel = Rectangle(center=(59, 0), width=118, height=100)
    drawing shingles {
        for i in range(7) {
            l = Line(((i + 1) * 15 mm, -48 mm), ((i + 1) * 15 mm, 48 mm))
        }
    }
}

assembly stable {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=220, height=130, corner_radius=5)
        # base frame = world shifted by base_y
        back_m = tab_and_slot(part="slot", length=wall_w, thickness=mat, tabs=3, tab=20 mm,
                              screw=0, clearance=0.2 mm, cx=0 mm, cy=back_y + mat / 2 - base_y)
        left_m = tab_and_slot(part="slot", length=depth, thickness=mat, tabs=2, tab=20 mm,
                              screw=0, clearance=0.2 mm, rotation=90 deg,
                              cx=-wall_w / 2 + mat / 2, cy=(back_y + front_y) / 2 - base_y)
        right_m = tab_and_slot(part="slot", length=depth, thickness=mat, tabs=2, tab=20 mm,
                               screw=0, clearance=0.2 mm, rotation=90 deg,
                               cx=wall_w / 2 - mat / 2, cy=(back_y + front_y) / 2 - base_y)
        drawing word {
            n = Text("NOEL", position=(0, -65 mm + 12.5 mm), size=12, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    solid back {
        # own frame: x centred, y = 0 the base's top, tabs to y = -mat
        gable = Polygon([(-100, 0), (100, 0), (100, 110), (0, 160), (-100, 110)])
        foot = Rectangle(bottom_left=(-100, -3), width=200, height=3)
        # the post reaches into the star past its lower notch (at 188 - 7 = 181)
        post = Rectangle(center=(0, 170), width=6, height=26)
        star = Star(center=(0, 188), points=5, outer_radius=16, inner_radius=7)
        t = tab_and_slot(part="tab", length=wall_w, thickness=mat, tabs=3, tab=20 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-mat)
        hole window {
            s = Star(center=(0, 125), points=5, outer_radius=12, inner_radius=5)
        }
    }

    left = side_wall()
    right = side_wall()
    roof_l = roof()
    roof_r = roof()

    # on the sheet
    RightOf(back, base, gap=8)
    AlignBottom(back, base)
    Below(left, base, gap=8)
    AlignLeft(left, base)
    RightOf(right, left, gap=8)
    AlignTop(right, left)
    RightOf(roof_l, right, gap=8)
    AlignTop(roof_l, right)
    RightOf(roof_r, roof_l, gap=8)
    AlignTop(roof_r, right)

    # assembled
    Place(base, position=(0, base_y, 0))
    Place(back, rotation=(90 deg, 0, 0), position=(0, back_y + mat, mat))
    # (x, y, z) -> (-z, -x, y): depth toward -y, thickness toward -x
    Place(right, rotation=(90 deg, 0, -90 deg), position=(wall_w / 2, back_y, mat))
    Place(left, rotation=(90 deg, 0, -90 deg), position=(-wall_w / 2 + mat, back_y, mat))
    Place(roof_r, rotation=(0, roof_angle, 0), position=(0, back_y - 50 mm, mat + apex))
    Place(roof_l, rotation=(0, roof_angle, 180 deg), position=(0, back_y - 50 mm, mat + apex))

    # the request's numbers
    assert base.plate.bb.width == 220 mm and base.plate.bb.height == 130 mm, "base 220 x 130"
    assert base_y + 65 mm >= back_y + mat, "the base's back edge is behind the back wall"
    assert abs((front_y - base_y) - (-65 mm) - 25 mm) < 0.01 mm, "a 25 mm strip in front"
    assert abs(base.word.n.position.y - (-65 mm + 12.5 mm)) < 0.01 mm, "NOEL in the strip's middle"
    assert back.gable.bb.width == 200 mm, "back wall 200 wide"
    assert back.gable.bb.height == 160 mm, "gable to 160"
    assert abs(back.window.s.center.y - back.foot.bb.top - 125 mm) < 0.01 mm, "star window 125 up"
    assert abs(back.star.center.y - back.foot.bb.top - 188 mm) < 0.01 mm, "star 188 up"
    assert len(base.back_m.slot) == 3 or base.back_m.tabs == 3, "three tabs on the back wall"
    assert left.body.bb.width == 90 mm and left.body.bb.height - mat == 110 mm, "side walls 90 x 110"
    assert abs(left.window.arch.center.x - left.body.bb.left - 45 mm) < 0.01 mm, "window 45 from the back"
    assert abs(left.window.sill.center.y - (left.body.bb.bottom + mat) - 60 mm) < 0.01 mm, "window 60 up"
    assert roof_l.panel.bb.width >= sqrt((wall_w / 2) ** 2 + (apex - eave) ** 2), "roof covers the slope"
    assert abs(roof_l.panel.bb.width * cos(roof_angle) - wall_w / 2 - 5 mm) < 0.6 mm, "about 5 mm past the eaves"
    assert len(roof_l.shingles.l) == 7, "seven shingle lines"
    assert back_y - front_y == depth, "side walls reach the front edge"
}
