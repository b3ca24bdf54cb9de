# Request: a Thanksgiving table centrepiece, a standing turkey cut from 4 mm ply. The body is a
# side-view silhouette: a 110 x 90 mm oval body whose centre is 60 mm up, a neck rising to a
# 30 mm head (its centre 132 mm up, 48 mm forward), a beak, a wattle, a 4 mm eye hole and an
# engraved wing. Behind it, crossing the body 45 mm behind the body's centre, stands a tail
# fan of seven feathers (90 x 32 mm ovals on a 100 mm half-disc hub, their centres on an 80 mm
# radius from 18 to 162 deg, 24 deg apart), each feather engraved with a word of thanks:
# FAMILY, FRIENDS, FOOD, HOME, HEALTH, LOVE, JOY. Body and fan cross-halve each other 43 mm
# each (0.2 clearance) and both are glued with two 15 mm tabs into an oval base 190 x 120,
# which has "GIVE THANKS" engraved in front of the body.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
fan_x = -45 mm        # where the fan crosses the body, from the body's centre
words = ["FAMILY", "FRIENDS", "FOOD", "HOME", "HEALTH", "LOVE", "JOY"]

def fa(i) = (18 + 24 * i) * 1 deg
# the body's top edge where the fan crosses it: its highest point over the slot's width
# (the slot's front side, 2.1 mm ahead of its middle), so the mouth clears the curved edge
back_top = 60 mm + 45 mm * sqrt(1 - ((fan_x + 2.1 mm) / 55 mm) ** 2)

assembly turkey {
    solid body {
        belly = Ellipse(center=(0, 60), rx=55, ry=45)
        stand = Rectangle(bottom_left=(-50, -t), width=90, height=40 + t)
        neck = Hull(Circle(center=(30, 95), radius=14), Circle(center=(48, 128), radius=11))
        head = Circle(center=(48, 132), radius=15)
        beak = Polygon([(58, 139), (76, 133), (59, 127)])
        wattle = Ellipse(center=(60, 116), rx=4, ry=9)
        hole eye {
            c = Circle(center=(53, 137), diameter=4)
        }
        drawing wing {
            outline = Ellipse(center=(-5, 62), rx=32, ry=19, rotation=-12 deg)
            f1 = Arc(center=(-40, 62), radius=22, start_angle=-40 deg, end_angle=40 deg)
            f2 = Arc(center=(-52, 62), radius=22, start_angle=-40 deg, end_angle=40 deg)
        }
        tabs = tab_and_slot(part="tab", length=90 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=-5, cy=-t)
        halving = cross_halving(depth=back_top - 43 mm, thickness=t, clearance=0.2 mm,
                                cx=fan_x, cy=back_top)
    }

    solid fan {
        hub = Sector(center=(0, 0), radius=50, start_angle=0 deg, end_angle=180 deg)
        foot = Rectangle(bottom_left=(-50, -t), width=100, height=t + 10)
        for i in range(7) {
            feather = Ellipse(center=(80 * cos(fa(i)), 80 * sin(fa(i))), rx=45, ry=16,
                              rotation=fa(i))
        }
        drawing thanks {
            for i in range(7) {
                w = Text(words[i], position=(85 * cos(fa(i)), 85 * sin(fa(i))), size=6,
                         valign="middle",
                         rotation=(fa(i) if i <= 3 else fa(i) - 180 deg))
            }
        }
        tabs = tab_and_slot(part="tab", length=100 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=0, cy=-t)
        halving = cross_halving(depth=43 mm, thickness=t, clearance=0.2 mm, rotation=180 deg,
                                cx=0, cy=0)
    }

    solid base {
        oval = Ellipse(center=(-5, 0), rx=95, ry=60)
        body_slots = tab_and_slot(part="slot", length=90 mm, thickness=t, tabs=2, tab=15 mm,
                                  screw=0, clearance=0.1 mm, cx=-5, cy=0)
        fan_slots = tab_and_slot(part="slot", length=100 mm, thickness=t, tabs=2, tab=15 mm,
                                 screw=0, clearance=0.1 mm, rotation=90 deg, cx=fan_x, cy=0)
        drawing motto {
            m = Text("GIVE THANKS", position=(15, -47), size=6)
        }
    }

    Place(base, position=(0, 0, 0))
    # body upright along x: its y -> z, thickness -> world -y
    Place(body, rotation=(90 deg, 0, 0), position=(0, t / 2, t))
    # fan upright across: its x -> world y, y -> z, thickness -> world x
    Place(fan, rotation=(90 deg, 0, 90 deg), position=(fan_x - t / 2, 0, t))

    # on the sheet
    RightOf(body, base, gap=8)
    AlignBottom(body, base)
    Above(fan, base, gap=8)
    AlignLeft(fan, base)

    assert len(fan.feather) == 7 and len(words) == 7, "seven feathers, seven words"
    assert body.belly.rx * 2 == 110 mm and body.belly.ry * 2 == 90 mm, "body 110 x 90"
    assert body.belly.center.y - body.stand.bb.bottom - t == 60 mm, "body centre 60 up"
    assert body.head.center.y - body.belly.center.y == 72 mm, "head centre 132 up"
    assert fan.feather[6].center.x < 0 and fan.feather[3].center.y - fan.hub.center.y == 80 mm, "feathers on r80"
    assert body.halving.cut.bb.center_x - body.belly.center.x == -45 mm, "fan 45 behind"
    assert base.oval.bb.width == 190 mm and base.oval.bb.height == 120 mm, "base 190 x 120"
}
