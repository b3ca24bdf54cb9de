// Issue 14: `units in` (inches), `//` as floor division before a closing bracket and brace,
// `//` comments, and a dotted import of the standard library.
units in
import stdlib.shapes

param n = 5   // five holes

solid plate {
    body = Rectangle(center=(0, 0), width=4, height=2)
    hole bore { c = Circle(center=(0, 0), radius=n//2 * 0.1) }
    // numbers that cross into another file's template need their unit: bare, they are in
    // the template file's mm, and a 0.5 mm pocket at x = 1.4 mm lay inside the bore (W0508)
    nut = hex_pocket(across_flats=0.5 in, cx=1.4 in)
}
