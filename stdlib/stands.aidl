# AIDL standard library: stands and holders of flat laser-cut parts.
#   import "std/stands.aidl"
# Each is an assembly: its parts laid out flat on the sheet around (cx, cy),
# `gap` apart, and placed in 3D with `Place` (`aidl render --assembled`
# shows the product standing on z = 0; the fit check W0517/W0518 runs).
# The joints are std/joints.aidl's; sizes are nominal (`kerf 0.15 mm` keeps
# them so when cut).

import "std/joints.aidl"

# A phone or tablet stand: two side supports leaning back at `angle`, crossed by a foot.
# Each support is a profile `height` tall with a ledge 6 mm up and a `lip`
# in front that holds the device (a channel 14 mm deep); its depth follows
# from the angle. The foot, `width` long and 40 mm tall, crosses both
# supports in cross-halving slots (`thickness` + `clearance` wide, 20 mm
# deep each). Members: `support` (a list of 2), `foot`.
def tablet_stand(width=120 mm, height=120 mm, angle=70 deg, lip=12 mm, thickness=3 mm,
                 clearance=0 mm, cx=0 mm, cy=0 mm) -> assembly {
    assert angle > 30 deg and angle < 85 deg, "the back leans at 30 to 85 degrees"
    assert width >= 60 mm and height >= 60 mm, "the stand is at least 60 mm wide and tall"
    t = thickness
    e = 6 mm                                   # the ledge the device stands on
    f = 40 mm                                  # the foot's height
    gap = 5 mm
    depth = (height - e) / tan(angle) + 60 mm  # the supports' footprint
    x5 = depth / 2 - 24 mm                     # the back's front face meets the ledge
    x6 = x5 - (height - e) / tan(angle)
    prof = [(-depth / 2, 0 mm), (depth / 2, 0 mm), (depth / 2, e + lip), (depth / 2 - 10 mm, e + lip),
            (depth / 2 - 10 mm, e), (x5, e), (x6, height), (x6 - 15 mm, height), (-depth / 2, 12 mm)]
    for i in range(2) {
        ox = cx + (2 * i - 1) * (depth + gap) / 2
        solid support {
            body = Polygon([(ox + q[0], cy + q[1]) for q in prof])
            Fixed(body)
            slot = cross_halving(depth=f / 2, thickness=t, clearance=clearance, rotation=180 deg,
                                 cx=ox, cy=cy)
        }
        # stood up across x, its front toward +y, crossing the foot at y = 0
        Place(support, rotation=(90 deg, 0, 90 deg),
              position=((2 * i - 1) * (width / 2 - 15 mm) - t / 2, -ox, -cy))
    }
    solid foot {
        body = Rectangle(center=(cx, cy - gap - f / 2), width=width, height=f)
        Fixed(body)
        for i in range(2) {
            slot = cross_halving(depth=f / 2, thickness=t, clearance=clearance,
                                 cx=cx + (2 * i - 1) * (width / 2 - 15 mm), cy=cy - gap)
        }
    }
    Place(foot, rotation=(90 deg, 0, 0), position=(-cx, t / 2, f + gap - cy))
}

# A book or laptop stand: two side supports sloping at `angle`, joined by two cross bars.
# The sides are `depth` deep, `height` tall at the front (with a 10 mm lip
# that stops the laptop sliding) and rise at `angle` toward the back; the
# bars, `width` long and `height` tall, cross them in cross-halving slots
# (`thickness` + `clearance` wide, half the bar deep) 30 mm from either
# end. Members: `side` (a list of 2), `bar` (a list of 2).
def laptop_stand(width=260 mm, depth=220 mm, height=30 mm, angle=15 deg, thickness=3 mm,
                 clearance=0 mm, cx=0 mm, cy=0 mm) -> assembly {
    assert angle >= 0 deg and angle < 45 deg, "the top slopes at 0 to 45 degrees"
    assert height >= 20 mm and depth >= 100 mm and width >= 100 mm, "at least 100 mm wide and deep, 20 mm tall"
    t = thickness
    gap = 5 mm
    back = height + depth * tan(angle)
    prof = [(-depth / 2, 0 mm), (depth / 2, 0 mm), (depth / 2, height + 10 mm),
            (depth / 2 - 6 mm, height + 10 mm), (depth / 2 - 6 mm, height + 6 mm * tan(angle)),
            (-depth / 2, back)]
    for i in range(2) {
        ox = cx + (2 * i - 1) * (depth + gap) / 2
        solid side {
            body = Polygon([(ox + q[0], cy + q[1]) for q in prof])
            Fixed(body)
            for k in range(2) {
                slot = cross_halving(depth=height / 2, thickness=t, clearance=clearance,
                                     rotation=180 deg, cx=ox + (2 * k - 1) * (depth / 2 - 30 mm), cy=cy)
            }
        }
        Place(side, rotation=(90 deg, 0, 90 deg),
              position=((2 * i - 1) * (width / 2 - 20 mm) - t / 2, -ox, -cy))
    }
    for k in range(2) {
        by = cy - gap - height / 2 - k * (height + gap)
        solid bar {
            body = Rectangle(center=(cx, by), width=width, height=height)
            Fixed(body)
            for i in range(2) {
                slot = cross_halving(depth=height / 2, thickness=t, clearance=clearance,
                                     cx=cx + (2 * i - 1) * (width / 2 - 20 mm), cy=by + height / 2)
            }
        }
        # stood up across the sides, 30 mm from the front and from the back
        Place(bar, rotation=(90 deg, 0, 0),
              position=(-cx, (2 * k - 1) * (depth / 2 - 30 mm) + t / 2, height / 2 - by))
    }
}
