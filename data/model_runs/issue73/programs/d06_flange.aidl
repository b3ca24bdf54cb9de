# 50 mm flange, 6 x 4 mm holes on a 38 mm bolt circle, 12 mm centre bore.
import "std/shapes.aidl"
solid flange {
    disc = Circle(center=(10, 10), diameter=50)
    holes = bolt_circle(count=6, pcd=38 mm, hole_d=4 mm)
    holes.bb.center == disc.center
    hole bore { c = Circle(center=(0, 0), diameter=12) }
    Concentric(bore.c, disc)
}
