# Request (signs): a round "SLOW 10" speed sign for a farm track, 300 mm across, from 6 mm
# exterior ply, to be painted after cutting.
# - A 30 mm wide border ring engraved filled (to paint red), leaving a 5 mm plain rim outside it.
# - "10" cut right through as bold stencil numerals 100 mm tall, centred 5 mm above the middle,
#   so the post shows through.
# - "SLOW" engraved 18 mm tall above the numerals and "km/h" engraved 16 mm tall below them.
# - Two 5.5 mm holes for M5 countersunk screws (10 mm heads) on the vertical centre line,
#   204 mm apart, inside the white field, to screw it to a post.

thickness 6 mm

param d = 300 mm, min = 200 mm, max = 600 mm
param band = 30 mm, min = 15 mm, max = 50 mm

solid sign {
    disc = Circle(center=(0, 0), diameter=d)
    drawing border {
        ring = Shell(Circle(center=(0, 0), radius=d / 2 - 5), -band, fill=true)
    }
    hole number {
        n = Text("10", (0, 5), size=100, font="sans:Bold", valign="middle", stencil=true)
    }
    drawing words {
        slow = Text("SLOW", (0, 80), size=18, valign="middle")
        unit = Text("km/h", (0, -75), size=16, valign="middle")
    }
    hole mount {
        top = Circle(center=(0, 102), diameter=5.5)
        bottom = Circle(center=(0, -102), diameter=5.5)
    }
    Countersink(mount, diameter=10)

    # the request's numbers
    assert disc.diameter == 300 mm, "300 across"
    assert number.n.size == 100 mm, "numerals 100 tall"
    assert number.n.position.y - disc.center.y == 5 mm, "5 above the middle"
    assert mount.top.center.y - mount.bottom.center.y == 204 mm, "holes 204 apart"
    assert mount.top.center.y + 5 mm < d / 2 - 5 mm - band, "holes inside the white field"
}
