# Request (kitchen): a cake divider for a 9 inch (230 mm) round cake, cut from 3 mm food-safe
# acrylic. A wheel 226 mm across laid on the iced cake and pressed lightly so its spokes mark
# 12 equal portions: an outer rim 12 mm wide, a hub 44 mm across, 12 spokes 4 mm wide from hub
# to rim, the first pointing straight up. The portion numbers 1 to 12 engraved 6 mm tall on the
# rim, in the middle of each portion, counting clockwise from the top. A lifting handle
# 60 mm wide and 45 mm tall (top corners rounded 15 mm, a 24 mm finger hole) stands upright in
# the hub, glued by one 24 mm tab through a mortise in the hub's centre.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
param portions = 12, min = 6, max = 16
OD = 226 mm
RIM = 12 mm
HUB_D = 44 mm
SPOKE_W = 4 mm
STEP = 360 deg / portions

assembly cake_divider {
    solid wheel {
        rim = Circle(center=(0, 0), diameter=OD)
        hub = Circle(center=(0, 0), diameter=HUB_D)
        spoke = Rectangle(center=(0, OD / 4), width=SPOKE_W, height=OD / 2 - RIM / 2 - 2 mm,
                          rotation=0)
        spokes = CircularPattern(spoke, portions, (0, 0))
        hole open {
            c = Circle(center=(0, 0), diameter=OD - 2 * RIM)
        }
        # the hole would empty the hub and spokes too: they are re-filled by a solid child
        solid web {
            h = Circle(center=(0, 0), diameter=HUB_D)
        }
        drawing numbers {
            track = Circle(center=(0, 0), radius=OD / 2 - RIM / 2, construction=true)
            for k in range(portions) {
                n = Text(str(k + 1), along=track, angle=90 deg - (k + 0.5) * STEP, size=6,
                         valign="middle")
            }
        }
        socket = tab_and_slot(part="slot", length=60 mm, thickness=T, tabs=1, tab=24 mm, screw=0,
                              cx=0 mm, cy=0 mm)
    }

    solid handle {
        grip = RoundedRectangle(bottom_left=(-30, 0), width=60, height=45,
                                corner_radii=[15, 15, 0, 0])
        hole finger {
            c = Circle(center=(0, 25), diameter=24)
        }
        tab = tab_and_slot(part="tab", length=60 mm, thickness=T, tabs=1, tab=24 mm, screw=0,
                           rotation=180 deg, cx=0 mm, cy=0 mm)
    }

    RightOf(handle, wheel, gap=10)
    AlignBottom(handle, wheel)

    # upright in the hub: its tab through the wheel
    Place(handle, position=(0, T / 2, 0), rotation=(90 deg, 0, 0))

    assert wheel.rim.diameter == 226 mm, "wheel 226 across"
    assert len(spokes) == 12, "12 portions"
    assert len(wheel.numbers.n) == 12, "numbers 1 to 12"
    assert wheel.hub.diameter == 44 mm, "hub 44"
    assert handle.grip.width == 60 mm and handle.grip.height == 45 mm, "handle 60 x 45"
    assert wheel.socket.slot[0].bb.width == 24 mm, "24 mm mortise"
}
