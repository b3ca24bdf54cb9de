# Pegboard screwdriver shelf: 120 x 40 mm plate; three screwdriver holes of 6, 9 and
# 12 mm diameter in a row along the plate's centre line, 30 mm apart (middle one centred);
# two hook tabs 5 mm wide x 12 mm long on the back (top) edge, 50.8 mm apart (2 pegboard
# pitches of 25.4 mm), centred.
param w = 120 mm, min = 100 mm, max = 200 mm
param d = 40 mm, min = 30 mm, max = 60 mm
thickness 3 mm

solid holder {
    plate = Rectangle(center=(0, 0), width=w, height=d)
    solid hook_l { t = Rectangle(center=(-25.4, 26), width=5, height=12) }
    solid hook_r { t = Rectangle(center=(25.4, 26), width=5, height=12) }
    Above(hook_l, plate)
    Above(hook_r, plate)
    At(hook_r.t.center, hook_l.t.center, dx=50.8)
    AlignCenterX(plate, [hook_l, hook_r])
    hole small { c = Circle(center=(-30, 0), diameter=6) }
    hole medium { c = Circle(center=(0, 0), diameter=9) }
    hole large { c = Circle(center=(30, 0), diameter=12) }
    At(medium.c.center, plate.center)
    At(small.c.center, medium.c.center, dx=-30)
    At(large.c.center, medium.c.center, dx=30)
    assert small.c.diameter == 6 mm and medium.c.diameter == 9 mm and large.c.diameter == 12 mm, "three sizes"
    assert hook_r.t.center.x - hook_l.t.center.x == 50.8 mm, "two pegboard pitches"
}
