# Coffee filter holder bracket (back plate, 4 mm acrylic) for #4 cone filters:
# a trapezoid 150 mm wide at the top, 90 mm at the bottom, 100 mm tall, corners
# rounded 4 mm. Two 4.5 mm screw holes with 9 mm countersinks, 18 mm below the top
# edge and 35 mm in from the plate's center line on each side. A 60 x 4.2 mm
# slot, centered, 12 mm above the bottom edge (its center), takes the tab of the
# front retaining strip. A 30 mm diameter half-round thumb notch cut into the top
# edge at its middle, for pulling a filter out.

units mm
thickness 4 mm

solid bracket {
    plate = Trapezoid(center=(0, 0), bottom_width=90, top_width=150, height=100)
    Fillet(plate, 4)   # only the plate's four corners: the tab slot stays square

    hole screw {
        c = Circle(center=(-35, 32), diameter=4.5)
    }
    At(screw.c.center, plate.top.midpoint, dx=-35, dy=-18)
    axis = Line(plate.top.midpoint, plate.bottom.midpoint, construction=true)
    screw2 = Mirrored(screw, about=axis)
    Countersink([screw, screw2], diameter=9)

    hole tab_slot {
        s = Rectangle(center=(0, -38), width=60, height=4.2)
    }
    At(tab_slot.s.center, plate.bottom.midpoint, dy=12)

    hole thumb {
        c = Circle(center=(0, 50), diameter=30)
    }
    Coincident(thumb.c.center, plate.top.midpoint)
}
