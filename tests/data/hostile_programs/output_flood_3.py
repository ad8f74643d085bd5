# class: output_flood
# expect: contained
# attack: prints 100 MB in pieces, then prints a 2**26-leaf shared list, then keeps printing inside a finally after the time-out
line = "move " * 20_000
try:
    for i in range(1000):
        print(line)
    leaf = [1]
    for level in range(26):
        leaf = [leaf, leaf]
    print(leaf)
finally:
    for i in range(10 ** 9):
        print(i, line)
