-- expect-exit: 0
-- expect-output: total = 10
DEBUT{}
local total = 0
for i = 1, 4 do total = total + i end
print(string.format('total = %d', total))
FIN{}
