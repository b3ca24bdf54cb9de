# Fidget spinner: a two-lobed bar spinner: three 22 mm bearing holes in a row at
# 38 mm centres, a body of 17 mm radius round each bearing, joined by a 26 mm
# waist, and an engraved ring 2 mm outside each outer bearing.

param c = 38 mm

solid spinner {
    mid = Circle(center=(0, 0), radius=17)
    lobe_l = Circle(center=(-c, 0), radius=17)
    lobe_r = Circle(center=(c, 0), radius=17)
    waist = Rectangle(center=(0, 0), width=2 * c, height=26)
    hole bearings {
        for i in range(3) {
            b = Circle(center=((i - 1) * c, 0), diameter=22)
        }
    }
    drawing rings {
        l = Circle(center=(-c, 0), radius=13)
        r = Circle(center=(c, 0), radius=13)
    }
}
