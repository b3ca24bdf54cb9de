# A small wall shelf: a board on two cross-halved brackets, screwed to the wall.
import "std/stands.aidl"

thickness 3 mm

assembly shelf {
    s = wall_shelf(length=300 mm, depth=120 mm, height=150 mm, thickness=3 mm, screw=4)
}
