# Request (kitchen): a salt-and-pepper caddy for the table, for two round shakers 45 mm across,
# in 6 mm ply. A base 120 x 140 mm with R12 corners. A carrying upright along the middle: 100 mm
# wide for its first 50 mm above the base, then 80 mm wide up to 150 mm with its top corners
# rounded R20 and a 50 x 22 mm hand hole centred 125 mm up; it is glued into the base with two
# 20 mm tabs. A shelf plate the same size as the base, with two 47 mm holes for the shakers
# 32 mm either side of the middle and a slot that lets it drop over the narrow part of the
# upright (0.2 mm clearance each side) onto the 10 mm shoulders, 50 mm above the base.
# "SALT" and "PEPPER" engraved 6 mm high beside their holes on the shelf.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
SHAKER = 45 mm
SHELF_H = 50 mm      # shoulders above the base's top

assembly cruet {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=120, height=140, corner_radius=12)
        mortise = tab_and_slot(part="slot", length=100 mm, thickness=T, tabs=2, tab=20 mm,
                               screw=0, cx=0 mm, cy=0 mm)
    }

    solid upright {
        lower = Rectangle(bottom_left=(-50, -T), width=100, height=SHELF_H + T)
        upper = RoundedRectangle(center=(0, 95), width=80, height=110,
                                 corner_radii=[20, 20, 0, 0])
        hole hand { grip = Slot(center=(0, 125), length=50, width=22) }
        tenons = tab_and_slot(part="tab", length=100 mm, thickness=T, tabs=2, tab=20 mm,
                              screw=0, rotation=180 deg, cx=0 mm, cy=-T)
    }

    solid shelf {
        body = RoundedRectangle(center=(0, 0), width=120, height=140, corner_radius=12)
        hole seats {
            salt = Circle(center=(0, 32), diameter=SHAKER + 2 mm)
            pepper = Circle(center=(0, -32), diameter=SHAKER + 2 mm)
        }
        hole pass { s = Rectangle(center=(0, 0), width=80 + 0.4, height=T + 0.4) }
        drawing labels {
            salt_t = Text("SALT", position=(0, 62.75), size=6, valign="middle")
            pepper_t = Text("PEPPER", position=(0, -62.75), size=6, valign="middle",
                            rotation=180 deg)
        }
    }

    # flat on the sheet
    RightOf(upright, base, gap=10)
    AlignBottom(upright, base)
    RightOf(shelf, upright, gap=10)
    AlignBottom(shelf, base)

    # assembled: the upright stands across the base's middle, the shelf on its shoulders
    Place(base, position=(0, 0, 0))
    Place(upright, position=(0, T / 2, T), rotation=(90 deg, 0, 0))
    Place(shelf, position=(0, 0, T + SHELF_H))

    # the request's numbers
    assert base.body.bb.width == 120 mm and base.body.bb.height == 140 mm, "base 120 x 140"
    assert upright.lower.bb.width == 100 mm and upright.upper.bb.width == 80 mm, "upright 100 / 80 wide"
    assert upright.lower.bb.top - upright.tenons.bb.top == 50 mm, "shoulders 50 above the base"
    assert upright.upper.bb.top - upright.tenons.bb.top == 150 mm, "upright 150 tall above the base"
    assert upright.hand.grip.center.y - upright.tenons.bb.top == 125 mm, "hand hole 125 up"
    assert shelf.seats.salt.diameter == 47 mm, "47 mm shaker holes"
    assert shelf.seats.salt.center.y - shelf.body.center.y == 32 mm, "32 mm off the middle"
    assert shelf.pass.s.width - upright.upper.bb.width == 0.4 mm, "0.2 mm each side"
    assert shelf.seats.salt.center.y - SHAKER / 2 - 1 mm - shelf.pass.s.bb.top >= 3 mm, "wall to the slot"
}
