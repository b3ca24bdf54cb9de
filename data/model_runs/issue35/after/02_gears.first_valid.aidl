import "std/gears.aidl"
# two meshing spur gears on a mounting plate with shaft bores
param m = 2 mm
cd = m * (20 + 40) / 2
assembly kit {
    pair = gear_pair(teeth1=20, teeth2=40, module=m, bore1=6 mm, bore2=8 mm)
    solid plate {
        body = Rectangle(center=(cd / 2, 0), width=cd + 100, height=100)
        hole b1 { c = Circle(center=(0, 0), diameter=6) }
        hole b2 { c = Circle(center=(cd, 0), diameter=8) }
        HorizontalDistance(b1.c.center, b2.c.center, cd)
        VerticalDistance(b1.c.center, b2.c.center, 0)
        AlignCenterY(b1, body)
        HorizontalDistance(body.left.midpoint, b1.c.center, 50)
    }
    Below(plate, pair, gap=10)
}
