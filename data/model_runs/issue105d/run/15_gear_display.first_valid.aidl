# Gear display: a 20-tooth and a 40-tooth spur gear (module 2 mm, 5 mm bores) in mesh,
# and their display plate 180 x 110 mm (6 mm rounded corners) with two 5 mm axle holes
# at the gears' centre distance (2 * (20 + 40) / 2 = 60 mm), on the plate's horizontal
# centre line, the pair centred left-right; "20 : 40" engraved 6 mm tall, 12 mm above the
# bottom edge. Laid flat: the gears lie 10 mm to the right of the plate, in mesh.
import "std/gears.aidl"
param module = 2 mm, min = 1 mm, max = 3 mm
thickness 3 mm

assembly display {
    pair = gear_pair(teeth1=20, teeth2=40, module=module, bore1=5 mm, bore2=5 mm)
    solid plate {
        body = RoundedRectangle(center=(-150, 0), width=180, height=110, corner_radius=6)
        hole axle1 { c = Circle(center=(-180, 0), diameter=5) }
        hole axle2 { c = Circle(center=(-120, 0), diameter=5) }
        AlignCenterY(axle1, body)
        At(axle2.c.center, axle1.c.center, dx=60)
        (axle1.c.center.x + axle2.c.center.x) / 2 == body.center.x
        drawing title { t = Text("20 : 40", (-150, -43), size=6) }
        At(title.t.position, body.bottom.midpoint, dy=12)
    }
    Gap(plate, pair, 10)
    AlignCenterY(plate, pair)
    assert pair.center_distance == 60 mm, "centre distance 60 mm"
    assert plate.axle2.c.center.x - plate.axle1.c.center.x == pair.center_distance, "axles at the centre distance"
    assert pair.gear2.hub.center.x - pair.gear1.hub.center.x == 60 mm, "gears in mesh at 60 mm"
}
