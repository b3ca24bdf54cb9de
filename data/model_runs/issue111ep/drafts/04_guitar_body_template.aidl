# Request (music): a routing template for my single-cutaway electric guitar body, 6 mm MDF,
# used with a 3/8" top-bearing pattern bit (so every inside corner of a route has at least
# a 5 mm radius). Body 414 mm long and 316 mm wide, the cutaway on the treble side (right,
# neck up). Routes through the template: the neck pocket 56 mm wide, its floor 76 mm below
# the body's top edge; a neck humbucker 71.5 x 39 mm whose top edge is 6 mm below the
# pocket; a bridge humbucker the same size, 90 mm further down; a control cavity 100 x 60 mm
# on the bass side of the lower bout. Two 6 mm holes on the centre line for dowel pins
# (60 mm above the body's middle line and 170 mm below it). My laser bed is 400 x 300 mm, so
# the template is cut in two halves at 40 mm below the middle line, locked by a sliding
# dovetail (3 tails, 15 mm deep) across the joint. Engraved: "SC-1 UPPER" and
# "SC-1 LOWER 6mm MDF".

import "std/joints.aidl"

units mm
thickness 6 mm
kerf 0.15 mm

# the body outline, counter-clockwise from the top centre (the top centre lies in the
# neck pocket); point 21 is the sharp inside corner where the cutaway meets the pocket
outline_pts = [(0, 196), (-60, 192), (-120, 165), (-150, 110), (-140, 50), (-122, 5),
               (-135, -50), (-158, -110), (-150, -170), (-100, -205), (0, -218),
               (100, -205), (150, -170), (158, -110), (140, -50), (124, 0), (132, 50),
               (128, 110), (110, 175), (90, 198), (65, 185), (45, 140), (20, 130)]
split_y = -40 mm
dt_depth = 15 mm
pocket_w = 56 mm
pocket_floor = 196 mm - 76 mm
pu_w = 71.5 mm
pu_h = 39 mm
neck_pu_y = pocket_floor - 6 mm - pu_h / 2
bridge_pu_y = neck_pu_y - 90 mm
r_in = 5 mm

assembly template {
    solid upper {
        outline = Spline(outline_pts, closed=true, corners=[22])
        keep = Rectangle(corner=(-200, split_y - dt_depth), opposite=(200, 260))
        body = Intersect(outline, keep)
        joint = dovetail(part="tail", length=300 mm, depth=dt_depth, tails=3, rotation=180 deg,
                         cx=0, cy=split_y)
        hole pocket {
            r = RoundedRectangle(corner=(-pocket_w / 2, pocket_floor), opposite=(pocket_w / 2, 205),
                                 corner_radii=[0, 0, r_in, r_in])
        }
        hole neck_pu {
            r = RoundedRectangle(center=(0, neck_pu_y), width=pu_w, height=pu_h, corner_radius=r_in)
        }
        hole bridge_pu {
            r = RoundedRectangle(center=(0, bridge_pu_y), width=pu_w, height=pu_h, corner_radius=r_in)
        }
        hole pin { c = Circle(center=(0, 60), diameter=6) }
        drawing name {
            # FIX after the first valid program: at (-75, 95) the R touched the neck
            # pickup route; moved up into the bass shoulder
            word = Text("SC-1 UPPER", position=(-88, 135), size=8, valign="middle")
        }
    }

    solid lower {
        outline = Spline(outline_pts, closed=true, corners=[22])
        keep = Rectangle(corner=(-200, -260), opposite=(200, split_y))
        body = Intersect(outline, keep)
        joint = dovetail(part="socket", length=300 mm, depth=dt_depth, tails=3, rotation=180 deg,
                         cx=0, cy=split_y)
        hole controls {
            r = RoundedRectangle(center=(-70, -125), width=100, height=60, corner_radius=r_in)
        }
        hole pin { c = Circle(center=(0, -170), diameter=6) }
        drawing name {
            word = Text("SC-1 LOWER 6mm MDF", position=(60, -110), size=8, valign="middle")
        }
    }

    # cutting layout: the lower half below the upper one; assembled they lock as drawn
    Below(lower, upper, gap=10)
    AlignCenterX(lower, upper)
    Place(upper, position=(0, 0, 0))
    Place(lower, position=(0, 0, 0))

    # the request's numbers
    assert outline_pts[0][1] - outline_pts[10][1] == 414 mm
    assert outline_pts[13][0] - outline_pts[7][0] == 316 mm
    assert upper.pocket.r.width == 56 mm
    assert 196 mm - upper.pocket.r.bb.bottom == 76 mm
    assert upper.pocket.r.bb.bottom - upper.neck_pu.r.bb.top == 6 mm
    assert upper.neck_pu.r.center.y - upper.bridge_pu.r.center.y == 90 mm
    assert upper.neck_pu.r.width == 71.5 mm and upper.neck_pu.r.height == 39 mm
    assert lower.controls.r.width == 100 mm and lower.controls.r.height == 60 mm
    assert upper.pin.c.center.y == 60 mm and lower.pin.c.center.y == -170 mm
    assert distance(upper.name, upper.neck_pu) >= 5 mm and distance(upper.name, upper.pocket) >= 5 mm
    assert distance(lower.name, lower.controls) >= 5 mm
    # each half fits the 400 x 300 bed
    assert upper.body.bb.width <= 400 mm and upper.bb.height <= 300 mm
    assert lower.body.bb.width <= 400 mm and lower.bb.height <= 300 mm
    # the routes stay clear of the dovetail band and of each other
    assert upper.bridge_pu.r.bb.bottom - (split_y) >= 10 mm
    assert split_y - dt_depth - lower.controls.r.bb.top >= 10 mm
    assert upper.neck_pu.r.bb.bottom - upper.pin.c.center.y >= 8 mm, "pin clear of the pickups"
    assert upper.pin.c.center.y - upper.bridge_pu.r.bb.top >= 8 mm, "pin clear of the pickups"
}
