# A three-lobe fidget spinner for 608 bearings (22 mm): a centre hub and three
# lobes 32 mm from the centre at 120 degrees, each lobe a 34 mm disc with a
# 22 mm bearing hole, joined to the hub by the convex hull, and three 10 mm
# round scallops between the lobes to save weight.
param arm = 32 mm

solid spinner {
    hub = Circle(center=(0, 0), diameter=34)
    lobe = Circle(center=(0, arm), diameter=34)
    lobes = CircularPattern(lobe, 3, hub.center)
    body = Hull(hub, lobes[0], lobes[1], lobes[2])
    hole bearing { c = Circle(center=(0, 0), diameter=22) }
    hole seat { c = Circle(center=(0, arm), diameter=22) }
    seats = CircularPattern(seat, 3, (0, 0))
    hole scallop { c = Circle(center=polar((0, 0), 26, 30 deg), diameter=10) }
    scallops = CircularPattern(scallop, 3, (0, 0))
}
