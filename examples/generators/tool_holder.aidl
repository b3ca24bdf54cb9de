# A pen holder: a finger-jointed box with a top plate of 2 x 3 holes.
import "std/stands.aidl"

thickness 3 mm

assembly desk {
    pens = tool_holder(length=100 mm, depth=70 mm, height=90 mm, thickness=3 mm, rows=2, cols=3, hole=16 mm)
}
