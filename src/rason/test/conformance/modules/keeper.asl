/* The keeper: the same stock module twice, in two namespaces. */
{ include("lib/stock.asl", apples) }
{ include("lib/stock.asl", pears) }
