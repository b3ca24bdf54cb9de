# Combination wrench: a tapered handle with an open jaw at one end and a
# 12-point ring (box) end at the other.
# Try: --set length=200  --set jaw=17  --set ring=10

param length = 150 mm  # center-to-center distance of the two heads
param jaw = 13 mm      # nut size (across flats) of the open end
param ring = 13 mm     # nut size (across flats) of the ring end

jaw_r = 1.4 * jaw     # radius of the open-end head
ring_r = 0.95 * ring  # radius of the ring-end head
tilt = 15 deg         # the open jaw is angled, as on a real wrench

solid wrench {
    # the handle tapers from the open end toward the ring end
    solid handle {
        bar = Polygon([(-length / 2, -0.45 * jaw), (length / 2, -0.35 * ring),
                       (length / 2, 0.35 * ring), (-length / 2, 0.45 * jaw)])
    }

    solid open_end {
        head = Circle(center=(-length / 2, 0), radius=jaw_r)
    }

    solid ring_end {
        head = Circle(center=(length / 2, 0), radius=ring_r)
    }

    # the jaw: a slot as wide as the nut, running from the head's center out
    # through its rim; cut from the whole wrench
    hole jaw_opening {
        gap = Slot(start=(-length / 2 - 0.5 * jaw * cos(tilt), -0.5 * jaw * sin(tilt)),
                   end=(-length / 2 - 1.9 * jaw * cos(tilt), -1.9 * jaw * sin(tilt)),
                   radius=jaw / 2)
    }

    # the ring: a 12-point star (two hexagons 30 degrees apart), built in a loop
    hole socket {
        r_out = ring / 2 / cos(30 deg)
        r_in = ring / 2 / cos(15 deg)
        for i in range(24) {
            r = r_out if i % 2 == 0 else r_in
            corner = (length / 2 + r * cos(i * 15 deg), r * sin(i * 15 deg))
        }
        star = Polygon(corner)  # after the loop, `corner` is the list of all 24
    }

    # engraved size markings on the handle
    drawing marks {
        open_size = Text(f"{jaw}", (-length / 2 + 1.6 * jaw_r, -0.175 * jaw), size=0.35 * jaw, anchor="start")
        ring_size = Text(f"{ring}", (length / 2 - 1.6 * ring_r, -0.175 * ring), size=0.35 * ring, anchor="end")
    }

    # the heads sit on the ends of the handle's axis
    Coincident(open_end.head.center, handle.bar.edges[3].midpoint)
    Coincident(ring_end.head.center, handle.bar.edges[1].midpoint)
    # the jaw's bottom is the open head's center; the star is centered in the ring head
    Distance(jaw_opening.gap.start, open_end.head.center, 0.5 * jaw)
    Angle(handle.bar.edges[3], jaw_opening.gap.spine, 90 deg - tilt)
    OnLine(open_end.head.center, jaw_opening.gap.spine)
    CenterInside(socket, ring_end.head)
    # the sizes on the handle's axis, the open one 1.6 head radii from its head
    AlignCenterY(marks, handle)
    marks.open_size.position.x == open_end.head.center.x + 1.6 * jaw_r
}
