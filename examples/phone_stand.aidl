# A phone stand of two flat pieces that slot into each other (a cross-halving
# joint): the support has a slot from its top edge down, the foot one from its
# bottom edge up, each as wide as the material and half as deep as the overlap.
# `Place` stands both pieces up, crossed at right angles, for the assembled view:
#   aidl render examples/phone_stand.aidl --assembled -o stand.3mf
# A slot narrower than the material makes the pieces collide (the fit check,
# W0517), so `slot`'s range stops at the sheet; with `min = 1 mm` written,
#   aidl check examples/phone_stand.aidl --set slot=2.5mm
# shows the collision.
# Try: --set angle=60deg

units mm
param slot = 3 mm, min = 3 mm, max = 6 mm, step = 0.5 mm  # never under the sheet: the pieces collide
param angle = 70 deg, min = 50 deg, max = 80 deg, step = 5 deg
thickness 3 mm

t = 3 mm        # the material
foot_h = 40 mm  # the foot's height: the pieces overlap over it, each slot half of it

assembly stand {
    # the leaning back, with a lip at its foot for the phone to rest on
    solid support {
        body = Polygon([(-40, 0), (40, 0), (40, 12), (30, 12), (30, 6), (25, 6),
                        (25 - 84 / tan(angle), 90), (10 - 84 / tan(angle), 90), (-40, 12)])
        Fixed(body)
        hole slot_cut {
            s = Rectangle(center=(0, foot_h / 2 + 50), width=slot, height=100)
        }
        Fixed(slot_cut)
    }
    # the foot that keeps it upright, crossing it from below (drawn beside it)
    solid foot {
        body = Rectangle(center=(100, foot_h / 2), width=70, height=foot_h)
        Fixed(body)
        hole slot_cut {
            s = Rectangle(center=(100, foot_h / 4 - 1), width=slot, height=foot_h / 2 + 2)
        }
        Fixed(slot_cut)
    }
    # standing up: the support in the x-z plane, the foot turned a quarter about z
    Place(support, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(foot, rotation=(90 deg, 0, 90 deg), position=(-t / 2, -100, 0))
}
