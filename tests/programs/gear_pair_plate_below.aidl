# issue 48: an agent wrote this through MCP; the Below read the gears' pinned teeth (6,264 unknowns,
# a 99 s redundancy search); now 26 unknowns and a fraction of a second
units mm

import "std/gears.aidl"

param module = 2 mm
param z1 = 15
param z2 = 30
param bore = 6 mm
param axle_d = 6 mm
param rim = 12 mm            # plate material around each axle

cd = module * (z1 + z2) / 2  # center distance: 45 mm

thickness 3 mm

assembly gearset {
    pair = gear_pair(teeth1=z1, teeth2=z2, module=module, bore1=bore, bore2=bore)
    Fixed(pair.gear1.hub.center)

    solid plate {
        body = RoundedRectangle(center=(cd / 2, -60), width=cd + 2 * rim, height=2 * rim,
                                corner_radius=rim / 2)
        hole axle1 { c = Circle(center=(0, -60), diameter=axle_d) }
        hole axle2 { c = Circle(center=(cd, -60), diameter=axle_d) }
        Fixed(body)                  # the plate frame moves; its holes stay put in it
        At(axle1.c.center, body.center, dx=-cd / 2)
        At(axle2.c.center, body.center, dx=cd / 2)
    }
    # the plate lies under the gears, its first axle hole under the pinion's center
    plate.axle1.c.center.x == pair.gear1.hub.center.x
    Below(plate, pair, gap=10)
    # assembled view: the plate under the gears, its holes on the gear axes
    assert abs(plate.axle2.c.center.x - pair.gear2.hub.center.x) < 0.001 mm, "the axle holes match the gear centers"
}
