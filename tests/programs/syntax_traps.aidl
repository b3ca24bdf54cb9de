// Issue 14: `units in` (inches), `//` as floor division before a closing bracket and brace,
// `//` comments, and a dotted import of the standard library.
units in
import stdlib.shapes

param n = 5   // five holes

solid plate {
    body = Rectangle(center=(0, 0), width=4, height=2)
    hole bore { c = Circle(center=(0, 0), radius=n//2 * 0.1) }
    nut = hex_pocket(across_flats=0.5, cx=1.4)
}
