# Request (science): a pendulum-wave demonstrator for the classroom, 6 mm birch ply.
# - 15 pendulums whose periods fit 51, 52, ... 65 swings into 60 s, so the row makes its
#   patterns and comes back in line every minute; pendulum k (0..14) is
#   L = g (T / 2 pi)^2 long with T = 60 s / (51 + k): 344 mm down to 212 mm (to the bob's centre).
# - A beam 440 mm between the uprights, 40 mm wide, lying flat with its top 426 mm above the
#   table, 15 string holes 3 mm, 25 mm apart, centred, 8 mm in front of its centre line; beside
#   each hole its pendulum's length in mm, engraved. A 20 x 6 mm tenon at each end of the beam
#   into a mortise in each upright.
# - Two uprights 80 mm wide standing on the base, glued in with two 15 mm tabs each.
# - Base 500 x 150 mm, corners r5, "PENDULUM WAVE - 60 s" engraved along its front.
import "std/joints.aidl"

thickness 6 mm

T = 6 mm
N = 15
PITCH = 25 mm
SPAN = 440 mm             # between the uprights' inner faces
UP_X = SPAN / 2 + T / 2   # the uprights' mid-planes
BEAM_Z = 420 mm           # the beam's underside above the table
G = 9810                  # mm / s^2

def period(k) = 60 / (51 + k)
def plen(k) = G * (period(k) / tau) ** 2

def upright() -> solid {
    # own frame: u = world y (depth), v = world z (height, table at v = 0)
    body = Rectangle(bottom_left=(-40, 0), width=80, height=BEAM_Z + T + 10)
    feet = tab_and_slot(part="tab", length=80 mm, thickness=T, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    mortise = tab_and_slot(part="slot", length=40 mm, thickness=T, tabs=1, tab=20 mm, screw=0,
                           cx=0 mm, cy=BEAM_Z + T / 2)
}

assembly pendulum_wave {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=500, height=150, corner_radius=5)
        left_slots = tab_and_slot(part="slot", length=80 mm, thickness=T, tabs=2, tab=15 mm,
                                  screw=0, rotation=90 deg, cx=-UP_X, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=80 mm, thickness=T, tabs=2, tab=15 mm,
                                   screw=0, rotation=90 deg, cx=UP_X, cy=0 mm)
        drawing title {
            t = Text("PENDULUM WAVE - 60 s", position=(0, -60), size=8, valign="middle")
        }
        assert title.bb.bottom >= body.bb.bottom + 4 mm, "title on the base"
        assert title.bb.top <= left_slots.slot[0].bb.bottom - 4 mm, "title in front of the uprights"
    }

    left = upright()
    right = upright()

    solid beam {
        # flat, in world x-y; tenon tips at the uprights' outer faces
        body = Rectangle(center=(0, 0), width=SPAN + 2 * T, height=40)
        tenon_l = tab_and_slot(part="tab", length=40 mm, thickness=T, tabs=1, tab=20 mm, screw=0,
                               rotation=90 deg, cx=-(SPAN / 2 + T), cy=0 mm)
        tenon_r = tab_and_slot(part="tab", length=40 mm, thickness=T, tabs=1, tab=20 mm, screw=0,
                               rotation=-90 deg, cx=SPAN / 2 + T, cy=0 mm)
        for k in range(N) {
            hole string { c = Circle(center=((k - (N - 1) / 2) * PITCH, -8), diameter=3) }
        }
        drawing lengths {
            for k in range(N) {
                t = Text(f"{plen(k):.0f}", position=((k - (N - 1) / 2) * PITCH, -3), size=4,
                         anchor="start", valign="middle", rotation=90 deg)
            }
        }
        assert string[1].c.center.x - string[0].c.center.x == 25 mm, "holes 25 mm apart"
        assert string[0].c.center.x + string[14].c.center.x == 2 * body.center.x, "holes centred"
        assert body.center.y - string[0].c.center.y == 8 mm, "holes 8 mm in front of the centre line"
        assert lengths.bb.top <= body.bb.top - 2 mm, "labels on the beam"
    }

    assert len(beam.string) == 15, "15 pendulums"
    assert abs(plen(0) - 344 mm) < 1 mm and abs(plen(14) - 212 mm) < 1 mm, "344 down to 212 mm"
    assert BEAM_Z + T == 426 mm, "beam top 426 mm up"
    assert BEAM_Z - T - plen(0) >= 40 mm, "the longest bob clears the base"
    assert left.body.bb.width == 80 mm, "uprights 80 mm wide"

    # 3D
    Place(base, position=(0, 0, 0))
    # uprights: (u, v, w) -> (w, u, v)
    Place(left, position=(-UP_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(UP_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(beam, position=(0, 0, BEAM_Z))

    # flat on the sheet
    Below(beam, base, gap=10)
    AlignLeft(beam, base)
    RightOf(left, base, gap=10)
    RightOf(right, left, gap=10)
    AlignTop(left, base)
    AlignTop(right, base)
}
