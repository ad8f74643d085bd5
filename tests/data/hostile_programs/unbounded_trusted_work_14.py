# class: unbounded_trusted_work
# expect: refused
# attack: a class whose base is an f-string whose expression part no quote style can write without a backslash: the guard's message for a bad base calls ast.unparse on it, which raises ValueError in the trusted process's static checker (find_violations runs outside the checker's try)
class A(f'''{"'" "'" "'" '"' '"' '"'}'''):
    pass
print('ran')
