# A finger-jointed enclosure for an 85 x 56 mm board, with standoff holes, two ports and a vented lid.
#   aidl render examples/generators/board_enclosure.aidl --assembled -o box.png
import "std/enclosures.aidl"

thickness 3 mm

assembly case {
    box = board_enclosure(width=85 mm, height=56 mm, depth=25 mm, thickness=3 mm,
                          ports=[["front", 20, 10, 4], ["right", 28, 14, 8]], vent="hex")
}
